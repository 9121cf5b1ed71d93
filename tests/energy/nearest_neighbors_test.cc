// The k-nearest and within-radius queries against brute force over seeded random points, the
// same for one and two threads.
#include "energy/nearest_neighbors.h"

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace lpd::energy {
namespace {

PointList RandomPoints(int count, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  PointList points;
  for (int i = 0; i < count; ++i) points.emplace_back(unit(random), unit(random), unit(random));
  return points;
}

TEST(NearestNeighbors, FindsTheKNearestByBruteForce) {
  const PointList points = RandomPoints(2000, 1);
  const PointList queries = RandomPoints(50, 2);
  const NearestNeighbors search(points);
  constexpr int kK = 40;
  search.ForEach(static_cast<int>(queries.size()), kK, 2, [&](int q) { return queries[q]; },
                 [&](int q, const int* nearest, const double* squared, int found) {
                   std::vector<std::pair<double, int>> all;
                   for (size_t i = 0; i < points.size(); ++i) {
                     all.emplace_back((points[i] - queries[q]).squaredNorm(), static_cast<int>(i));
                   }
                   std::sort(all.begin(), all.end());
                   ASSERT_EQ(found, kK);
                   for (int b = 0; b < kK; ++b) {
                     EXPECT_EQ(nearest[b], all[b].second);
                     EXPECT_DOUBLE_EQ(squared[b], all[b].first);
                   }
                 });
}

TEST(NearestNeighbors, FindsThePointsWithinARadiusByBruteForceForAnyThreadCount) {
  const PointList points = RandomPoints(2000, 3);
  const PointList queries = RandomPoints(50, 4);
  const NearestNeighbors search(points);
  auto squared_radius = [](int q) { return 0.01 * (1 + q % 5); };
  std::vector<std::vector<int>> found[2];
  for (int threads : {1, 2}) {
    std::vector<std::vector<int>>& result = found[threads - 1];
    result.resize(queries.size());
    search.ForEachWithin(static_cast<int>(queries.size()), threads,
                         [&](int q) { return queries[q]; }, squared_radius,
                         [&](int q, const std::vector<int>& within) { result[q] = within; });
  }
  EXPECT_EQ(found[0], found[1]);
  for (size_t q = 0; q < queries.size(); ++q) {
    std::vector<int> expected;
    for (size_t i = 0; i < points.size(); ++i) {
      if ((points[i] - queries[q]).squaredNorm() < squared_radius(static_cast<int>(q))) {
        expected.push_back(static_cast<int>(i));
      }
    }
    std::vector<int> within = found[1][q];
    std::sort(within.begin(), within.end());
    EXPECT_EQ(within, expected) << "query " << q;
    EXPECT_FALSE(expected.empty());
  }
}

}  // namespace
}  // namespace lpd::energy
