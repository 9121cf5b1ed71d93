#include "experiments/evaluation/benchmark_metrics.h"

#include <cmath>
#include <stdexcept>

#include "energy/point_kd_tree.h"

namespace lpd::experiments {
namespace {

using energy::PointList;

double MeanSquare(const std::vector<double>& distances) {
  double sum = 0.0;
  for (double d : distances) sum += d * d;
  return sum / static_cast<double>(distances.size());
}

}  // namespace

std::vector<double> NearestDistances(const PointList& from, const PointList& to,
                                     int num_threads) {
  if (to.empty()) throw std::invalid_argument("no points to measure against");
  const energy::PointListAdaptor adaptor{to};
  energy::L2PointKdTree tree(3, adaptor,
                             nanoflann::KDTreeSingleIndexAdaptorParams(energy::kKdTreeLeafSize));
  tree.buildIndex();
  std::vector<double> distances(from.size());
  const long n = static_cast<long>(from.size());
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (long i = 0; i < n; ++i) {
    int index;
    double squared;
    nanoflann::KNNResultSet<double, int> result(1);
    result.init(&index, &squared);
    tree.findNeighbors(result, from[i].data(), nanoflann::SearchParams());
    distances[i] = std::sqrt(squared);
  }
  return distances;
}

double ChamferDistanceX1e4(const PointList& result, const PointList& clean, int num_threads) {
  if (result.empty()) throw std::invalid_argument("cannot score an empty point set");
  // Distances scale with the radius and do not move with the centre.
  const double radius = UnitSphereOf(clean).radius;
  const double cd = MeanSquare(NearestDistances(result, clean, num_threads)) +
                    MeanSquare(NearestDistances(clean, result, num_threads));
  return 1e4 * cd / (radius * radius);
}

double PointToMeshDistanceX1e4(const PointList& result, const GroundTruth& truth,
                               int num_threads) {
  if (result.empty()) throw std::invalid_argument("cannot score an empty point set");
  if (!truth.surface_distances || !truth.surface_to_points_distances ||
      truth.frame_points.empty()) {
    return NAN;
  }
  const double radius = UnitSphereOf(truth.frame_points).radius;
  const double p2m = MeanSquare(truth.surface_distances(result, num_threads)) +
                     MeanSquare(truth.surface_to_points_distances(result, num_threads));
  return 1e4 * p2m / (radius * radius);
}

}  // namespace lpd::experiments
