// lpd: a triangle mesh as a ground truth, and its area-uniform sampling.
#ifndef LPD_EXPERIMENTS_SHAPES_TRIANGLE_MESH_H_
#define LPD_EXPERIMENTS_SHAPES_TRIANGLE_MESH_H_

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "energy/point3.h"
#include "experiments/shapes/procedural_shape.h"

namespace lpd::experiments {

struct TriangleMesh {
  energy::PointList vertices;
  std::vector<std::array<int, 3>> triangles;
};

// Reads OFF, OBJ, PLY (or any format CGAL's polygon-soup reader knows); polygons are
// fan-triangulated. Throws std::runtime_error naming the file if it cannot be read or has no
// faces. Implemented with CGAL in its own translation unit (mesh_io.cc).
TriangleMesh ReadTriangleMesh(const std::string& path);

// Writes OFF or ASCII PLY, chosen by the extension (.off, .ply), through io::AtomicOutputFile:
// the file appears only complete, and an existing file is refused unless `overwrite`.
// Throws std::runtime_error on another extension or a write error.
void WriteTriangleMesh(const std::string& path, const TriangleMesh& mesh, bool overwrite);
// Throws std::runtime_error unless `path` ends in .off or .ply.
void CheckTriangleMeshPath(const std::string& path);

// `count` samples drawn uniformly by area (a triangle is picked with probability proportional
// to its area, then a uniform point in it), with the unit normal of their triangle. The same
// (count, seed) always gives the same samples. Throws if the mesh has zero area.
SurfaceSamples SampleTriangleMesh(const TriangleMesh& mesh, int count, uint64_t seed);

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_SHAPES_TRIANGLE_MESH_H_
