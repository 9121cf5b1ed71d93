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

energy::PointList Gather(const energy::PointList& points, const std::vector<int>& indices) {
  energy::PointList gathered;
  gathered.reserve(indices.size());
  for (int i : indices) gathered.push_back(points[i]);
  return gathered;
}

// Splits points[first, last) of `indices` at the median of the box's longest axis until each
// part holds at most `tile_points`.
void Split(const energy::PointList& points, std::vector<int>::iterator first,
           std::vector<int>::iterator last, int tile_points,
           std::vector<std::vector<int>>* tiles) {
  const long count = last - first;
  if (count <= tile_points) {
    std::vector<int> tile(first, last);
    std::sort(tile.begin(), tile.end());
    tiles->push_back(std::move(tile));
    return;
  }
  Eigen::AlignedBox3d box;
  for (auto it = first; it != last; ++it) box.extend(points[*it]);
  int axis = 0;
  box.sizes().maxCoeff(&axis);
  const auto middle = first + count / 2;
  std::nth_element(first, middle, last,
                   [&](int a, int b) { return points[a][axis] < points[b][axis]; });
  Split(points, first, middle, tile_points, tiles);
  Split(points, middle, last, tile_points, tiles);
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

std::vector<std::vector<int>> PlanTiles(const energy::PointList& points, int tile_points) {
  if (tile_points < 1) throw std::invalid_argument("tile_points must be >= 1");
  std::vector<int> indices(points.size());
  std::iota(indices.begin(), indices.end(), 0);
  std::vector<std::vector<int>> tiles;
  if (!points.empty()) Split(points, indices.begin(), indices.end(), tile_points, &tiles);
  return tiles;
}

Eigen::AlignedBox3d BoundingBoxOf(const energy::PointList& points,
                                  const std::vector<int>& indices) {
  Eigen::AlignedBox3d box;
  for (int i : indices) box.extend(points[i]);
  return box;
}

std::vector<int> HaloOf(const energy::PointList& points, const std::vector<int>& own,
                        double width) {
  const Eigen::AlignedBox3d box = BoundingBoxOf(points, own);
  std::vector<uint8_t> is_own(points.size(), 0);
  for (int i : own) is_own[i] = 1;
  std::vector<int> halo;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!is_own[i] && box.exteriorDistance(points[i]) <= width) halo.push_back(static_cast<int>(i));
  }
  return halo;
}

double HaloWidth(const energy::PointList& own_points, const DenoiseOptions& options,
                 double halo_radii) {
  const int threads = options.settings.num_threads;
  NeighborhoodSize size;
  if (options.choose_k) {
    size = ChooseThinning(own_points, options.neighborhood, threads).size;
  } else {
    size = ChooseNeighborhoodSize(own_points, options.neighborhood, threads);
    size.k = options.problem.k;
  }
  const double diagonal = energy::BoundingBoxDiagonal(own_points);
  return halo_radii * size.spacing * diagonal * std::sqrt(size.k / kPi);
}

TileOutcome DenoiseTile(const energy::PointList& points, const std::vector<int>& own,
                        const DenoiseOptions& options, const TilingOptions& tiling) {
  const Clock::time_point start = Clock::now();
  const energy::PointList own_points = Gather(points, own);
  const std::vector<int> halo =
      HaloOf(points, own, HaloWidth(own_points, options, tiling.halo_radii));
  energy::PointList tile_points = own_points;
  for (int i : halo) tile_points.push_back(points[i]);
  const DenoiseResult result = DenoisePointSet(tile_points, options);

  TileOutcome tile;
  tile.own = own;
  const size_t n = own.size();
  tile.projected.assign(result.projected.begin(), result.projected.begin() + n);
  tile.normals.assign(result.normals.begin(), result.normals.begin() + n);
  const PointIndicators& all = result.indicators;
  tile.indicators.outlier_score.assign(all.outlier_score.begin(), all.outlier_score.begin() + n);
  tile.indicators.feature_score.assign(all.feature_score.begin(), all.feature_score.begin() + n);
  tile.indicators.is_outlier.assign(all.is_outlier.begin(), all.is_outlier.begin() + n);
  tile.indicators.is_feature.assign(all.is_feature.begin(), all.is_feature.begin() + n);
  tile.kept.assign(result.kept.begin(), result.kept.begin() + n);
  tile.halo = halo;
  tile.k = result.neighborhood.k;
  tile.solved_points = result.solved_points;
  tile.iterations = result.summary.num_iterations;
  tile.converged = result.summary.termination == TerminationType::kConvergence;
  tile.seconds = SecondsSince(start);
  return tile;
}

void ResizeForTiles(size_t num_points, DenoiseResult* total) {
  total->projected.resize(num_points);
  total->normals.resize(num_points);
  total->indicators.outlier_score.resize(num_points);
  total->indicators.feature_score.resize(num_points);
  total->indicators.is_outlier.resize(num_points);
  total->indicators.is_feature.resize(num_points);
  total->kept.resize(num_points);
}

void PlaceTile(const TileOutcome& tile, DenoiseResult* total) {
  for (size_t a = 0; a < tile.own.size(); ++a) {
    const int i = tile.own[a];
    total->projected[i] = tile.projected[a];
    total->normals[i] = tile.normals[a];
    total->indicators.outlier_score[i] = tile.indicators.outlier_score[a];
    total->indicators.feature_score[i] = tile.indicators.feature_score[a];
    total->indicators.is_outlier[i] = tile.indicators.is_outlier[a];
    total->indicators.is_feature[i] = tile.indicators.is_feature[a];
    total->kept[i] = tile.kept[a];
    total->num_outliers += tile.indicators.is_outlier[a];
    total->num_removed += !tile.kept[a];
    total->num_features += tile.indicators.is_feature[a];
  }
}

}  // namespace lpd::solvers
