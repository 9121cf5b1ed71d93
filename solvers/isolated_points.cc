#include "solvers/isolated_points.h"

#include <cmath>
#include <sstream>

#include "energy/normalization.h"
#include "energy/nearest_neighbors.h"
#include "energy/spatial_order.h"
#include "solvers/median.h"

namespace lpd::solvers {

bool IsolationOptions::IsValid(std::string* error) const {
  std::ostringstream out;
  if (neighbors < 1) {
    out << "isolation_neighbors must be >= 1, got " << neighbors;
  } else if (!(radius_factor == 0.0 || radius_factor > 1.0) || !std::isfinite(radius_factor)) {
    out << "isolation_factor must be 0 (off) or > 1, got " << radius_factor;
  } else {
    return true;
  }
  *error = out.str();
  return false;
}

std::vector<uint8_t> FlagIsolatedPoints(const energy::PointList& points,
                                        const std::vector<uint8_t>& kept,
                                        const IsolationOptions& options, int num_threads) {
  std::vector<uint8_t> isolated(points.size(), 0);
  energy::PointList kept_points;
  std::vector<int> rows;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!kept[i]) continue;
    rows.push_back(static_cast<int>(i));
    kept_points.push_back(points[i]);
  }
  const int n = static_cast<int>(rows.size());
  const int m = options.neighbors;
  if (options.radius_factor == 0.0 || n <= m) return isolated;
  // In Morton order consecutive searches visit the same tree nodes and points (1M points in
  // input order: 9.0 s, in Morton order: 2.0 s); the normalized frame keeps squared
  // distances finite for any input coordinates.
  const std::vector<int> order = energy::MortonOrder(kept_points);
  const energy::Frame frame = energy::ComputeNormalizingFrame(kept_points);
  energy::PointList in_order(n);
  std::vector<int> rows_in_order(n);
  for (int r = 0; r < n; ++r) {
    in_order[r] = frame.ToNormalized(kept_points[order[r]]);
    rows_in_order[r] = rows[order[r]];
  }
  kept_points = std::move(in_order);
  rows = std::move(rows_in_order);
  const energy::NearestNeighbors search(kept_points);
  auto kept_point = [&kept_points](int r) { return kept_points[r]; };
  std::vector<double> squared_radius(n);
  // The search finds the point itself first, so entry m is its m-th neighbour.
  search.ForEach(n, m + 1, num_threads, kept_point,
                 [&squared_radius, m](int r, const int*, const double* squared_distances, int) {
                   squared_radius[r] = squared_distances[m];
                 });
  const double squared_factor = options.radius_factor * options.radius_factor;
  std::vector<double> radii_to_reorder = squared_radius;
  const double global_limit = squared_factor * Median(&radii_to_reorder);
  std::vector<int> candidates;
  for (int r = 0; r < n; ++r) {
    if (squared_radius[r] > global_limit) candidates.push_back(r);
  }
  // The candidates' own neighbourhoods: a region sampled more sparsely than the rest has
  // neighbours as far apart as its points, a point off the surface has not.
  search.ForEach(
      static_cast<int>(candidates.size()), m + 1, num_threads,
      [&](int c) { return kept_points[candidates[c]]; },
      [&](int c, const int* nearest, const double*, int) {
        std::vector<double> neighbor_radius(m);
        for (int a = 1; a <= m; ++a) neighbor_radius[a - 1] = squared_radius[nearest[a]];
        const int r = candidates[c];
        isolated[rows[r]] = squared_radius[r] > squared_factor * Median(&neighbor_radius);
      });
  return isolated;
}

}  // namespace lpd::solvers
