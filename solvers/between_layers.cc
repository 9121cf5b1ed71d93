#include "solvers/between_layers.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Eigenvalues>

#include "energy/nearest_neighbors.h"
#include "energy/sheet_split.h"
#include "solvers/median.h"
#include "solvers/merged_sides.h"

namespace lpd::solvers {
namespace {

// The median of sorted[begin, end) and kMedianAbsToSigma times the median absolute
// deviation about it.
void RobustSpread(const std::vector<double>& sorted, int begin, int end, double* median,
                  double* deviation) {
  *median = sorted[begin + (end - begin) / 2];
  thread_local std::vector<double> distances;
  distances.resize(end - begin);
  for (int a = begin; a < end; ++a) distances[a - begin] = std::abs(sorted[a] - *median);
  *deviation = kMedianAbsToSigma * Median(&distances);
}

// Two layers read around a centre: heights along `normal` from `origin`.
struct Layers {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  energy::Point3 origin = energy::Point3::Zero();
  double median[2] = {0.0, 0.0};
  double spread[2] = {0.0, 0.0};  // robust deviations
  double gap = 0.0;
  bool found = false;
};

// The dominant direction of the normals of the outputs `nearest[0, found)`.
Eigen::Vector3d LayerNormal(const energy::PointList& normals, const int* nearest, int found) {
  Eigen::Matrix3d normal_moment = Eigen::Matrix3d::Zero();
  for (int b = 0; b < found; ++b) {
    const energy::Point3& n = normals[nearest[b]];
    normal_moment += n * n.transpose();
  }
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(normal_moment).eigenvectors().col(2);
}

// The layers along `normal` around `origin` of the kLayerNeighbors outputs nearest across it
// among `candidates` (between_layers.h).
Layers ReadLayers(const energy::PointList& outputs, const std::vector<int>& candidates,
                  const Eigen::Vector3d& normal, const energy::Point3& origin,
                  double deviation) {
  Layers layers;
  layers.origin = origin;
  layers.normal = normal;
  // (distance across the normal squared, output), ties by the output's index.
  thread_local std::vector<std::pair<double, int>> across;
  across.resize(candidates.size());
  for (size_t b = 0; b < candidates.size(); ++b) {
    const energy::Point3 step = outputs[candidates[b]] - origin;
    const double height = normal.dot(step);
    across[b] = {step.squaredNorm() - height * height, candidates[b]};
  }
  const int found = std::min(static_cast<int>(across.size()), kLayerNeighbors);
  std::partial_sort(across.begin(), across.begin() + found, across.end());
  thread_local std::vector<energy::Point3> local;
  thread_local std::vector<double> heights, sorted;
  local.resize(found);
  heights.resize(found);
  for (int b = 0; b < found; ++b) {
    local[b] = outputs[across[b].second];
    heights[b] = normal.dot(local[b] - origin);
  }
  sorted = heights;
  std::sort(sorted.begin(), sorted.end());
  const int min_run = std::max(1, static_cast<int>(std::ceil(kMinLayerShare * found)));
  const energy::TwoRuns runs = energy::BestTwoRuns(sorted, min_run);
  const int lower_size = runs.lower_size;
  const double within = runs.within;
  if (lower_size == 0 || !(within > 0.0)) return layers;
  layers.gap = runs.upper_mean - runs.lower_mean;
  if (!(layers.gap > kMinLayerGapDeviations * deviation &&
        layers.gap < kMaxLayerGapDeviations * deviation)) {
    return layers;
  }
  if (!(layers.gap > kMinLayerSeparation * std::sqrt(within / found))) return layers;
  const double threshold = 0.5 * (sorted[lower_size - 1] + sorted[lower_size]);
  if (!(energy::FootprintDifference(local, heights, layers.normal, origin, threshold) <
        kMaxLayerFootprintDifference)) {
    return layers;
  }
  RobustSpread(sorted, 0, lower_size, &layers.median[0], &layers.spread[0]);
  RobustSpread(sorted, lower_size, found, &layers.median[1], &layers.spread[1]);
  layers.found = true;
  return layers;
}

// The height along layers.normal by which the output o (input p) moves onto the layer nearer
// to p, where o lies between the two layers; false where it does not.
bool MoveOntoLayer(const Layers& layers, const energy::Point3& o, const energy::Point3& p,
                   double* move) {
  const double height = layers.normal.dot(o - layers.origin);
  const double off[2] = {layers.median[0] - height, layers.median[1] - height};
  const int nearer = std::abs(off[0]) < std::abs(off[1]) ? 0 : 1;
  const double margin =
      std::max(kBetweenLayerSpreads * layers.spread[nearer], kBetweenLayerGapShare * layers.gap);
  if (!(std::abs(off[nearer]) > margin)) return false;
  const double input_height = layers.normal.dot(p - layers.origin);
  const int side = std::abs(input_height - layers.median[0]) <
                           std::abs(input_height - layers.median[1])
                       ? 0
                       : 1;
  *move = off[side];
  return true;
}

}  // namespace

energy::PointList MoveBetweenLayerPointsOntoLayers(const energy::PointList& inputs,
                                                   const energy::PointList& outputs,
                                                   const energy::PointList& normals,
                                                   const std::vector<uint8_t>& movable,
                                                   int num_threads, int* moved) {
  if (moved) *moved = 0;
  energy::PointList result = outputs;
  std::vector<int> anchors;
  for (size_t i = 0; i < outputs.size(); ++i) {
    if (movable[i] && normals[i].squaredNorm() > 0.0) anchors.push_back(static_cast<int>(i));
  }
  const int count = static_cast<int>(anchors.size());
  if (count < kLayerNeighbors) return result;
  const double deviation = OffsetDeviation(inputs, outputs, normals, anchors);
  if (!(deviation > 0.0)) return result;
  energy::PointList anchor_points(count);
  for (int r = 0; r < count; ++r) anchor_points[r] = outputs[anchors[r]];
  // The layers around every kLayerCentreStride-th anchor.
  const int num_centres = (count + kLayerCentreStride - 1) / kLayerCentreStride;
  energy::PointList centre_points(num_centres);
  for (int c = 0; c < num_centres; ++c) centre_points[c] = anchor_points[c * kLayerCentreStride];
  std::vector<Layers> layers(num_centres);
  // The normal from each centre's kLayerNeighbors nearest; the layers from the anchors
  // within sqrt(kLayerReachSquared) times the farthest of them.
  std::vector<Eigen::Vector3d> normal(num_centres);
  std::vector<double> reach(num_centres);
  const energy::NearestNeighbors search(anchor_points);
  search.ForEach(num_centres, kLayerNeighbors, num_threads,
                 [&](int c) { return centre_points[c]; },
                 [&](int c, const int* nearest, const double* squared_distances, int found) {
                   thread_local std::vector<int> neighbors;
                   neighbors.resize(found);
                   for (int b = 0; b < found; ++b) neighbors[b] = anchors[nearest[b]];
                   normal[c] = LayerNormal(normals, neighbors.data(), found);
                   reach[c] = kLayerReachSquared * squared_distances[found - 1];
                 });
  search.ForEachWithin(num_centres, num_threads, [&](int c) { return centre_points[c]; },
                       [&](int c) { return reach[c]; },
                       [&](int c, const std::vector<int>& within) {
                         thread_local std::vector<int> candidates;
                         candidates.resize(within.size());
                         for (size_t b = 0; b < within.size(); ++b) {
                           candidates[b] = anchors[within[b]];
                         }
                         layers[c] = ReadLayers(outputs, candidates, normal[c], centre_points[c],
                                                deviation);
                       });
  // Each anchor against the layers of its nearest centre.
  std::vector<uint8_t> moves(count, 0);
  const energy::NearestNeighbors centre_search(centre_points);
  centre_search.ForEach(count, 1, num_threads, [&](int r) { return anchor_points[r]; },
                        [&](int r, const int* nearest, const double*, int) {
                          const Layers& around = layers[nearest[0]];
                          const int i = anchors[r];
                          double move = 0.0;
                          if (around.found && MoveOntoLayer(around, outputs[i], inputs[i], &move)) {
                            result[i] = outputs[i] + move * around.normal;
                            moves[r] = 1;
                          }
                        });
  if (moved) *moved = static_cast<int>(std::count(moves.begin(), moves.end(), 1));
  return result;
}

}  // namespace lpd::solvers
