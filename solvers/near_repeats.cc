#include "solvers/near_repeats.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

#include "energy/nearest_neighbors.h"
#include "energy/normalization.h"

namespace lpd::solvers {

std::vector<int> NearRepeatRepresentatives(const energy::PointList& points, int num_threads) {
  const int n = static_cast<int>(points.size());
  std::vector<int> representative(n);
  std::iota(representative.begin(), representative.end(), 0);
  const int searched = kNearRepeatNeighbors + 1;  // a point finds itself first
  if (n < searched) return representative;
  // Searched in the normalized frame: squared distances of far-flung coordinates overflow.
  const energy::Frame frame = energy::ComputeNormalizingFrame(points);
  energy::PointList normalized(n);
  for (int i = 0; i < n; ++i) normalized[i] = frame.ToNormalized(points[i]);
  const energy::NearestNeighbors search(normalized);
  // The local spacing is sqrt(pi / K) d_K, so the squared radius is (r^2 pi / K) d_K^2.
  const double squared_radius_per_squared_d_k =
      kNearRepeatRadius * kNearRepeatRadius * M_PI / kNearRepeatNeighbors;
  // A near repeat has a point within the radius, so where fewer than the share of an even
  // sample of the points have one, near repeats are fewer too (up to the sample's error).
  if (n > kNearRepeatSample) {
    std::vector<uint8_t> has_close_point(kNearRepeatSample);
    auto sampled = [n](int q) {
      return static_cast<int>(static_cast<int64_t>(q) * n / kNearRepeatSample);
    };
    search.ForEach(
        kNearRepeatSample, searched, num_threads, [&](int q) { return normalized[sampled(q)]; },
        [&](int q, const int*, const double* squared, int) {
          has_close_point[q] =
              squared[1] < squared_radius_per_squared_d_k * squared[kNearRepeatNeighbors];
        });
    const int close = static_cast<int>(
        std::count(has_close_point.begin(), has_close_point.end(), uint8_t{1}));
    if (close < kMinNearRepeatShare * kNearRepeatSample) return representative;
  }
  // Each point's neighbours within its radius: the first within[r] of nearest's row r.
  std::vector<int> nearest(static_cast<size_t>(n) * kNearRepeatNeighbors);
  std::vector<uint8_t> within(n);
  search.ForEach(
      n, searched, num_threads, [&normalized](int q) { return normalized[q]; },
      [&](int q, const int* found_nearest, const double* squared, int) {
        const double squared_radius =
            squared_radius_per_squared_d_k * squared[kNearRepeatNeighbors];
        int count = 0;
        while (count < kNearRepeatNeighbors && squared[count + 1] < squared_radius) ++count;
        within[q] = static_cast<uint8_t>(count);
        std::copy_n(found_nearest + 1, count,
                    nearest.begin() + static_cast<size_t>(q) * kNearRepeatNeighbors);
      });
  int repeats = 0;
  for (int r = 0; r < n; ++r) {
    const int* close = nearest.data() + static_cast<size_t>(r) * kNearRepeatNeighbors;
    for (int c = 0; c < within[r]; ++c) {
      if (close[c] < r && representative[close[c]] == close[c]) {
        representative[r] = close[c];
        ++repeats;
        break;
      }
    }
  }
  if (repeats < kMinNearRepeatShare * n) std::iota(representative.begin(), representative.end(), 0);
  return representative;
}

}  // namespace lpd::solvers
