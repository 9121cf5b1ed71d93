#include "solvers/tiling.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "energy/normalization.h"
#include "energy/wall_clock.h"
#include "solvers/neighborhood_size.h"
#include "solvers/thinning.h"

namespace lpd::solvers {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Splits points[first, last) of `indices` across the box's longest axis until each part
// holds at most `capacity`, into the fewest parts that allows, L = ceil(count / capacity),
// of near-equal size: the cut leaves floor(L / 2) parts' worth on the low side. Returns the
// node's index in tree->nodes.
int Split(const energy::PointList& points, std::vector<int>::iterator first,
          std::vector<int>::iterator last, int capacity, TileTree* tree) {
  const int node = static_cast<int>(tree->nodes.size());
  tree->nodes.emplace_back();
  const long count = last - first;
  if (count <= capacity) {
    tree->nodes[node].tile = tree->num_tiles++;
    return node;
  }
  Eigen::AlignedBox3d box;
  for (auto it = first; it != last; ++it) box.extend(points[*it]);
  int axis = 0;
  box.sizes().maxCoeff(&axis);
  const long parts = (count + capacity - 1) / capacity;
  const auto middle = first + count * (parts / 2) / parts;
  auto below = [&](int a, int b) { return points[a][axis] < points[b][axis]; };
  std::nth_element(first, middle, last, below);
  // The low side ends at its largest coordinate (points equal to it go low, as Locate sends
  // them).
  const double value = points[*std::max_element(first, middle, below)][axis];
  const int low = Split(points, first, middle, capacity, tree);
  const int high = Split(points, middle, last, capacity, tree);
  TileTree::Node& split = tree->nodes[node];
  split.axis = axis;
  split.value = value;
  split.low = low;
  split.high = high;
  return node;
}

}  // namespace

bool TilingOptions::IsValid(std::string* error) const {
  std::ostringstream out;
  if (tile_points < 0) {
    out << "tile_points must be >= 0 (0: no tiling), got " << tile_points;
  } else if (!(halo_radii > 0.0 && std::isfinite(halo_radii))) {
    out << "halo_radii must be positive, got " << halo_radii;
  } else {
    return true;
  }
  *error = out.str();
  return false;
}

int TileTree::Locate(const energy::Point3& p) const {
  int node = 0;
  while (nodes[node].axis >= 0) {
    node = p[nodes[node].axis] <= nodes[node].value ? nodes[node].low : nodes[node].high;
  }
  return nodes[node].tile;
}

std::vector<double> TileTree::Flatten() const {
  std::vector<double> values = {static_cast<double>(num_tiles)};
  for (const Node& node : nodes) {
    values.insert(values.end(), {static_cast<double>(node.axis), node.value,
                                 static_cast<double>(node.low), static_cast<double>(node.high),
                                 static_cast<double>(node.tile)});
  }
  return values;
}

TileTree TileTree::Unflatten(const std::vector<double>& values) {
  TileTree tree;
  tree.num_tiles = static_cast<int>(values.at(0));
  for (size_t at = 1; at + 5 <= values.size(); at += 5) {
    tree.nodes.push_back({static_cast<int>(values[at]), values[at + 1],
                          static_cast<int>(values[at + 2]), static_cast<int>(values[at + 3]),
                          static_cast<int>(values[at + 4])});
  }
  return tree;
}

TileTree PlanTileTree(const energy::PointList& points, int capacity) {
  if (capacity < 1) throw std::invalid_argument("tile_points must be >= 1");
  std::vector<int> indices(points.size());
  std::iota(indices.begin(), indices.end(), 0);
  TileTree tree;
  Split(points, indices.begin(), indices.end(), capacity, &tree);
  return tree;
}

std::vector<std::vector<int>> PlanTiles(const energy::PointList& points, int tile_points) {
  const TileTree tree = PlanTileTree(points, tile_points);
  std::vector<std::vector<int>> tiles(tree.num_tiles);
  for (size_t i = 0; i < points.size(); ++i) {
    tiles[tree.Locate(points[i])].push_back(static_cast<int>(i));
  }
  return tiles;
}

std::vector<int> HaloOf(const energy::PointList& points, const std::vector<int>& own,
                        double width) {
  Eigen::AlignedBox3d box;
  std::vector<uint8_t> is_own(points.size(), 0);
  for (int i : own) {
    box.extend(points[i]);
    is_own[i] = 1;
  }
  std::vector<int> halo;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!is_own[i] && InHalo(box, width, points[i])) halo.push_back(static_cast<int>(i));
  }
  return halo;
}

double HaloWidth(const energy::PointList& own_points, const DenoiseOptions& options,
                 double halo_radii) {
  const int threads = options.settings.num_threads;
  NeighborhoodSize size;
  if (options.choose_k) {
    size = ChooseThinning(own_points, options.ProbeOptions(), threads).size;
  } else {
    size = ChooseNeighborhoodSize(own_points, options.ProbeOptions(), threads);
    size.k = options.problem.k;
  }
  const double diagonal = energy::BoundingBoxDiagonal(own_points);
  return halo_radii * size.spacing * diagonal * std::sqrt(size.k / kPi);
}

TileOutcome DenoiseTile(const energy::PointList& own_points,
                        const energy::PointList& halo_points, const DenoiseOptions& options) {
  const Clock::time_point start = Clock::now();
  energy::PointList points = own_points;
  points.insert(points.end(), halo_points.begin(), halo_points.end());
  const DenoiseResult result = DenoisePointSet(points, options);
  TileOutcome tile;
  const size_t n = own_points.size();
  tile.projected.assign(result.projected.begin(), result.projected.begin() + n);
  tile.normals.assign(result.normals.begin(), result.normals.begin() + n);
  const PointIndicators& all = result.indicators;
  tile.indicators.outlier_score.assign(all.outlier_score.begin(), all.outlier_score.begin() + n);
  tile.indicators.feature_score.assign(all.feature_score.begin(), all.feature_score.begin() + n);
  tile.indicators.is_outlier.assign(all.is_outlier.begin(), all.is_outlier.begin() + n);
  tile.indicators.is_feature.assign(all.is_feature.begin(), all.is_feature.begin() + n);
  tile.kept.assign(result.kept.begin(), result.kept.begin() + n);
  tile.k = result.neighborhood.k;
  tile.solved_points = result.solved_points;
  tile.iterations = result.summary.num_iterations;
  tile.converged = result.summary.termination == TerminationType::kConvergence;
  tile.seconds = SecondsSince(start);
  return tile;
}

}  // namespace lpd::solvers
