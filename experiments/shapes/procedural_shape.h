// lpd: a procedural ground-truth shape: a union of analytic surface patches plus its sharp
// feature curves.
//
// Sampling is area-uniform over the whole surface and seeded, so a (shape, count, seed)
// triple always gives the same points. Distances to the surface and to the features are exact.
#ifndef LPD_EXPERIMENTS_SHAPES_PROCEDURAL_SHAPE_H_
#define LPD_EXPERIMENTS_SHAPES_PROCEDURAL_SHAPE_H_

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "energy/point3.h"
#include "experiments/shapes/feature_curves.h"
#include "experiments/shapes/surface_patches.h"

namespace lpd::experiments {

struct SurfaceSamples {
  energy::PointList points;
  energy::PointList normals;  // outward unit normals, one per point
};

class ProceduralShape {
 public:
  ProceduralShape(std::string description, std::vector<std::unique_ptr<SurfacePatch>> patches,
                  std::vector<FeatureSegment> segments, std::vector<FeatureArc> arcs);

  // For example "cone(apex_angle=60, radius=0.5)".
  const std::string& description() const { return description_; }
  double Area() const { return area_; }
  int num_patches() const { return static_cast<int>(patches_.size()); }
  bool has_features() const { return !segments_.empty() || !arcs_.empty(); }

  // `count` area-uniform samples; the same (count, seed) always gives the same samples.
  SurfaceSamples Sample(int count, uint64_t seed) const;

  double DistanceToSurface(const energy::Point3& p) const;
  // Distance to the nearest sharp feature curve (infinity for a shape without any).
  double DistanceToFeatures(const energy::Point3& p) const;

 private:
  std::string description_;
  std::vector<std::unique_ptr<SurfacePatch>> patches_;
  std::vector<FeatureSegment> segments_;
  std::vector<FeatureArc> arcs_;
  double area_ = 0.0;
};

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_SHAPES_PROCEDURAL_SHAPE_H_
