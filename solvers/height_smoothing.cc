#include "solvers/height_smoothing.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "energy/nearest_neighbors.h"
#include "solvers/movable_rows.h"

namespace lpd::solvers {

energy::PointList SmoothHeights(const energy::PointList& outputs,
                                const energy::PointList& normals,
                                const std::vector<uint8_t>& movable, double band, int pairs,
                                int num_threads) {
  const std::vector<int> rows = MovableRowsWithNormal(movable, normals);  // those that take part
  energy::PointList result = outputs;
  const int count = static_cast<int>(rows.size());
  if (pairs <= 0 || count < 2 || !(band > 0.0)) return result;
  energy::PointList current(count);
  for (int r = 0; r < count; ++r) current[r] = outputs[rows[r]];
  const int searched = std::min(kHeightNeighbors + 1, count);  // with itself
  // N_i of each point, read once: the first used[r] of its `searched` slots.
  std::vector<int> neighbors(static_cast<size_t>(count) * searched);
  std::vector<int> used(count, 0);
  const double min_cosine = std::cos(kHeightMaxAngleDegrees * M_PI / 180.0);
  const energy::NearestNeighbors search(current);
  search.ForEach(count, searched, num_threads, [&current](int r) { return current[r]; },
                 [&](int r, const int* nearest, const double*, int found) {
                   const energy::Point3& n = normals[rows[r]];
                   int* kept = neighbors.data() + static_cast<size_t>(r) * searched;
                   for (int a = 0; a < found; ++a) {
                     const int j = nearest[a];
                     if (std::abs(n.dot(normals[rows[j]])) < min_cosine) continue;
                     if (!(std::abs(n.dot(current[j] - current[r])) < band)) continue;
                     kept[used[r]++] = j;
                   }
                 });
  energy::PointList next(count);
  for (int round = 0; round < 2 * pairs; ++round) {
    const double factor = round % 2 == 0 ? kTaubinLambda : kTaubinMu;
#pragma omp parallel num_threads(num_threads)
    {
      std::vector<double> heights(searched);
#pragma omp for schedule(static)
      for (int r = 0; r < count; ++r) {
        const energy::Point3& n = normals[rows[r]];
        const int* kept = neighbors.data() + static_cast<size_t>(r) * searched;
        const int size = used[r];
        if (size == 0) {
          next[r] = current[r];
          continue;
        }
        for (int a = 0; a < size; ++a) heights[a] = n.dot(current[kept[a]] - current[r]);
        std::sort(heights.begin(), heights.begin() + size);
        const double median = size % 2 == 1
                                  ? heights[size / 2]
                                  : 0.5 * (heights[size / 2 - 1] + heights[size / 2]);
        next[r] = current[r] + (factor * median) * n;
      }
    }
    current.swap(next);
  }
  for (int r = 0; r < count; ++r) result[rows[r]] = current[r];
  return result;
}

}  // namespace lpd::solvers
