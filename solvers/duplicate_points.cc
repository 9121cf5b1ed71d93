#include "solvers/duplicate_points.h"

#include <algorithm>
#include <numeric>

namespace lpd::solvers {

std::vector<int> FirstOccurrences(const energy::PointList& points) {
  const int n = static_cast<int>(points.size());
  std::vector<int> first(n);
  std::iota(first.begin(), first.end(), 0);
  // Finite points sorted by coordinates, then by index: each run of equal points starts at
  // its first occurrence. (Non-finite points stay out: NaN has no order.)
  std::vector<int> order;
  order.reserve(n);
  for (int i = 0; i < n; ++i) {
    if (points[i].allFinite()) order.push_back(i);
  }
  auto less = [&points](int a, int b) {
    const energy::Point3& p = points[a];
    const energy::Point3& q = points[b];
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    if (p.z() != q.z()) return p.z() < q.z();
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  for (size_t r = 1; r < order.size(); ++r) {
    if (points[order[r]] == points[order[r - 1]]) first[order[r]] = first[order[r - 1]];
  }
  return first;
}

}  // namespace lpd::solvers
