#include "solvers/isolated_points.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "energy/normalization.h"
#include "energy/point_kd_tree.h"

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
  std::vector<int> rows;
  for (size_t i = 0; i < points.size(); ++i) {
    if (kept[i]) rows.push_back(static_cast<int>(i));
  }
  const int n = static_cast<int>(rows.size());
  const int m = options.neighbors;
  if (options.radius_factor == 0.0 || n <= m) return isolated;
  energy::PointList kept_points(n);
  for (int r = 0; r < n; ++r) kept_points[r] = points[rows[r]];
  // The normalized frame keeps squared distances finite for any input coordinates.
  const energy::Frame frame = energy::ComputeNormalizingFrame(kept_points);
  for (energy::Point3& p : kept_points) p = frame.ToNormalized(p);
  energy::PointListAdaptor adaptor{kept_points};
  energy::L2PointKdTree tree(3, adaptor,
                             nanoflann::KDTreeSingleIndexAdaptorParams(energy::kKdTreeLeafSize));
  tree.buildIndex();
  std::vector<double> squared_radius(n);
#pragma omp parallel num_threads(num_threads)
  {
    std::vector<int> nearest(m + 1);
    std::vector<double> squared_distances(m + 1);
#pragma omp for schedule(static)
    for (int r = 0; r < n; ++r) {
      // The search finds the point itself first, so entry m is its m-th neighbour.
      tree.knnSearch(kept_points[r].data(), m + 1, nearest.data(), squared_distances.data());
      squared_radius[r] = squared_distances[m];
    }
  }
  std::vector<double> sorted = squared_radius;
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
  const double limit = options.radius_factor * options.radius_factor * sorted[n / 2];
  for (int r = 0; r < n; ++r) isolated[rows[r]] = squared_radius[r] > limit;
  return isolated;
}

}  // namespace lpd::solvers
