// lpd: the catalogue of procedural ground-truth shapes, built from a name and parameters.
//
//   box       size_x=1 size_y=0.8 size_z=0.6      six faces, twelve edges
//   cube      size=1
//   sphere    radius=0.5                          smooth, no features
//   cylinder  radius=0.5 height=1                 two planar caps, two circular edges
//   cone      apex_angle=60 radius=0.5            apex angle in degrees (Fig. 17), base disk
//   cad_part  sweep=270                           a FANDISK-like turned part: planar,
//             cylindrical and conical patches, convex and concave straight and circular
//             edges; a lathe profile revolved over `sweep` degrees and closed by planar cuts
//   sheets    size=1 gap=0.02                     two parallel open squares `gap` apart (a
//             thin part without its rim); a plate is box:size_x=1,size_y=1,size_z=THICKNESS
#ifndef LPD_EXPERIMENTS_SHAPES_SHAPE_CATALOG_H_
#define LPD_EXPERIMENTS_SHAPES_SHAPE_CATALOG_H_

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "experiments/shapes/procedural_shape.h"

namespace lpd::experiments {

struct ShapeSpec {
  std::string name;
  std::map<std::string, double> parameters;  // unset parameters take their defaults
};

// Parses "NAME" or "NAME:key=value,key=value" (for example "cone:apex_angle=30"); throws
// std::invalid_argument on malformed text. Names and keys are checked by MakeShape.
ShapeSpec ParseShapeSpec(const std::string& text);

// Throws std::invalid_argument naming an unknown shape, an unknown parameter or a bad value.
ProceduralShape MakeShape(const ShapeSpec& spec);

// The shape names and, for each, its parameters with their defaults.
const std::map<std::string, std::map<std::string, double>>& ShapeParameterDefaults();

// A closed solid of revolution: the profile (r_i, z_i), r >= 0, runs counterclockwise in the
// (r, z) half-plane from a point on the axis to a point on the axis, and is turned about the
// z axis over `sweep_degrees`; below 360 the two cut half-planes close it, which needs the
// profile's z to be non-decreasing. Every profile corner is a sharp edge.
ProceduralShape MakeSolidOfRevolution(const std::string& description,
                                      const std::vector<std::pair<double, double>>& profile,
                                      double sweep_degrees);

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_SHAPES_SHAPE_CATALOG_H_
