#include "experiments/evaluation/ground_truth.h"

#include <sstream>

#include "energy/normalization.h"
#include "experiments/evaluation/benchmark_metrics.h"

namespace lpd::experiments {

GroundTruth ShapeGroundTruth(std::shared_ptr<const ProceduralShape> shape, int num_samples,
                             uint64_t seed) {
  GroundTruth truth;
  std::ostringstream description;
  description << shape->description() << ", " << num_samples << " samples, seed " << seed;
  truth.description = description.str();
  truth.samples = shape->Sample(num_samples, seed).points;
  truth.diagonal = energy::BoundingBoxDiagonal(truth.samples);
  truth.surface_distances = [shape](const energy::PointList& points, int num_threads) {
    std::vector<double> distances(points.size());
    const long n = static_cast<long>(points.size());
#pragma omp parallel for schedule(static) num_threads(num_threads)
    for (long i = 0; i < n; ++i) distances[i] = shape->DistanceToSurface(points[i]);
    return distances;
  };
  truth.frame_points = truth.samples;
  truth.surface_to_points_distances = [samples = truth.samples](const energy::PointList& points,
                                                                int num_threads) {
    return NearestDistances(samples, points, num_threads);
  };
  if (shape->has_features()) {
    truth.feature_distance = [shape](const energy::Point3& p) {
      return shape->DistanceToFeatures(p);
    };
  }
  return truth;
}

GroundTruth PointSetGroundTruth(energy::PointList points, const std::string& description) {
  GroundTruth truth;
  truth.description = description;
  truth.diagonal = energy::BoundingBoxDiagonal(points);
  truth.samples = std::move(points);
  return truth;
}

}  // namespace lpd::experiments
