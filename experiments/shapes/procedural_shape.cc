#include "experiments/shapes/procedural_shape.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace lpd::experiments {

ProceduralShape::ProceduralShape(std::string description,
                                 std::vector<std::unique_ptr<SurfacePatch>> patches,
                                 std::vector<FeatureSegment> segments,
                                 std::vector<FeatureArc> arcs)
    : description_(std::move(description)),
      patches_(std::move(patches)),
      segments_(std::move(segments)),
      arcs_(std::move(arcs)) {
  if (patches_.empty()) throw std::invalid_argument("a shape needs at least one patch");
  for (const auto& patch : patches_) area_ += patch->Area();
}

SurfaceSamples ProceduralShape::Sample(int count, uint64_t seed) const {
  if (count < 0) throw std::invalid_argument("sample count must be >= 0");
  std::vector<double> areas;
  for (const auto& patch : patches_) areas.push_back(patch->Area());
  std::discrete_distribution<size_t> pick(areas.begin(), areas.end());
  std::mt19937_64 rng(seed);
  SurfaceSamples samples;
  samples.points.reserve(count);
  samples.normals.reserve(count);
  for (int n = 0; n < count; ++n) {
    const SurfacePoint point = patches_[pick(rng)]->Sample(&rng);
    samples.points.push_back(point.position);
    samples.normals.push_back(point.normal);
  }
  return samples;
}

double ProceduralShape::DistanceToSurface(const energy::Point3& p) const {
  double best = INFINITY;
  for (const auto& patch : patches_) best = std::min(best, patch->Distance(p));
  return best;
}

double ProceduralShape::DistanceToFeatures(const energy::Point3& p) const {
  double best = INFINITY;
  for (const FeatureSegment& segment : segments_) best = std::min(best, segment.Distance(p));
  for (const FeatureArc& arc : arcs_) best = std::min(best, arc.Distance(p));
  return best;
}

}  // namespace lpd::experiments
