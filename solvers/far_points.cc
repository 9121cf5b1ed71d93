#include "solvers/far_points.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace lpd::solvers {

bool FarPointOptions::IsValid(std::string* error) const {
  std::ostringstream out;
  if (!(bulk_fraction > 0.5 && bulk_fraction < 1.0)) {
    out << "far_points bulk fraction must be in (0.5, 1), got " << bulk_fraction;
  } else if (!(factor == 0.0 || (factor >= 2.0 && std::isfinite(factor)))) {
    out << "far_factor must be 0 (off) or a finite number >= 2, got " << factor;
  } else {
    return true;
  }
  *error = out.str();
  return false;
}

std::vector<uint8_t> FlagFarPoints(const energy::PointList& points,
                                   const FarPointOptions& options) {
  const size_t n = points.size();
  std::vector<uint8_t> far(n, 0);
  if (options.factor == 0.0 || n < 2) return far;
  // The coordinate-wise median: no stray point can move it past the bulk.
  energy::Point3 median;
  std::vector<double> values(n);
  for (int axis = 0; axis < 3; ++axis) {
    for (size_t i = 0; i < n; ++i) values[i] = points[i][axis];
    const auto middle = values.begin() + n / 2;
    std::nth_element(values.begin(), middle, values.end());
    median[axis] = *middle;
  }
  std::vector<double> distances(n);
  for (size_t i = 0; i < n; ++i) distances[i] = (points[i] - median).norm();
  std::vector<double> sorted = distances;
  const size_t bulk = std::min(n - 1, static_cast<size_t>(options.bulk_fraction * n));
  std::nth_element(sorted.begin(), sorted.begin() + bulk, sorted.end());
  const double limit = options.factor * sorted[bulk];
  if (!(limit > 0.0)) return far;
  for (size_t i = 0; i < n; ++i) far[i] = distances[i] > limit;
  return far;
}

}  // namespace lpd::solvers
