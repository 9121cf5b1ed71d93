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

// Brute force: (squared distance to `query`, index) of every point, nearest first, equal
// distances by index.
std::vector<std::pair<double, int>> ByDistance(const PointList& points, const Point3& query) {
  std::vector<std::pair<double, int>> all;
  for (size_t i = 0; i < points.size(); ++i) {
    all.emplace_back((points[i] - query).squaredNorm(), static_cast<int>(i));
  }
  std::sort(all.begin(), all.end());
  return all;
}

// The k nearest of `query` a search found (`found` of them) against brute force: the same
// indices and the same squared distances, bit for bit.
void ExpectBruteForceNearest(const PointList& points, const Point3& query, int k,
                             const int* nearest, const double* squared, int found) {
  const auto all = ByDistance(points, query);
  ASSERT_EQ(found, k);
  for (int b = 0; b < k; ++b) {
    ASSERT_EQ(nearest[b], all[b].second) << "k " << k << " b " << b;
    ASSERT_EQ(squared[b], all[b].first);
  }
}

TEST(NearestNeighbors, FindsTheKNearestByBruteForce) {
  const PointList points = RandomPoints(2000, 1);
  const PointList queries = RandomPoints(50, 2);
  const NearestNeighbors search(points);
  constexpr int kK = 40;
  search.ForEach(static_cast<int>(queries.size()), kK, 2, [&](int q) { return queries[q]; },
                 [&](int q, const int* nearest, const double* squared, int found) {
                   const auto all = ByDistance(points, queries[q]);
                   ASSERT_EQ(found, kK);
                   for (int b = 0; b < kK; ++b) {
                     EXPECT_EQ(nearest[b], all[b].second);
                     EXPECT_DOUBLE_EQ(squared[b], all[b].first);
                   }
                 });
}

// From kRadiusFirstMinK on, a query starts from a radius guessed from the last query's: queries
// in spatial order, far queries that miss the guess, and duplicate points (equal distances,
// ordered by index) give the brute-force result for one and two threads.
TEST(NearestNeighbors, FindsTheKNearestFromAGuessedRadiusByBruteForce) {
  PointList points = RandomPoints(3000, 5);
  for (int i = 0; i < 200; ++i) points.push_back(points[7 * i]);  // duplicates
  PointList queries = points;
  std::sort(queries.begin(), queries.end(),
            [](const Point3& a, const Point3& b) { return a.x() < b.x(); });
  queries.resize(400);
  for (int q = 0; q < 400; q += 40) queries[q] += Point3(5.0 + q, 0.0, 0.0);  // far away
  const NearestNeighbors search(points);
  for (int k : {NearestNeighbors::kRadiusFirstMinK, 250}) {
    for (int threads : {1, 2}) {
      int checked = 0;
      search.ForEach(
          static_cast<int>(queries.size()), k, threads, [&](int q) { return queries[q]; },
          [&](int q, const int* nearest, const double* squared, int found) {
            SCOPED_TRACE(testing::Message() << "query " << q);
            ExpectBruteForceNearest(points, queries[q], k, nearest, squared, found);
#pragma omp atomic
            ++checked;
          });
      EXPECT_EQ(checked, static_cast<int>(queries.size()));
    }
  }
}

// Points repeated more than k times: the k-th nearest is at distance 0 for most queries, so no
// cell grid is built and the tree gathers; the result is still brute force's.
TEST(NearestNeighbors, FindsTheKNearestAmongPointsRepeatedMoreThanKTimes) {
  const PointList distinct = RandomPoints(40, 7);
  PointList points;
  for (int copy = 0; copy < 30; ++copy) {
    points.insert(points.end(), distinct.begin(), distinct.end());
  }
  const NearestNeighbors search(points);
  const int k = NearestNeighbors::kRadiusFirstMinK;
  search.ForEach(static_cast<int>(points.size()), k, 2, [&](int q) { return points[q]; },
                 [&](int q, const int* nearest, const double* squared, int found) {
                   ExpectBruteForceNearest(points, points[q], k, nearest, squared, found);
                 });
}

TEST(NearestNeighbors, FindsAllPointsWhenFewerThanKFromAGuessedRadius) {
  const PointList points = RandomPoints(150, 6);
  const NearestNeighbors search(points);
  const int k = 200;
  search.ForEach(20, k, 1, [&](int q) { return points[q]; },
                 [&](int q, const int* nearest, const double* squared, int found) {
                   ASSERT_EQ(found, 150);
                   EXPECT_EQ(nearest[0], q);
                   for (int b = 1; b < found; ++b) EXPECT_LE(squared[b - 1], squared[b]);
                 });
}

template <typename SquaredRadius>
void ExpectWithinByBruteForce(const PointList& points, const PointList& queries,
                              const NearestNeighbors& search,
                              const SquaredRadius& squared_radius) {
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
    EXPECT_EQ(expected.empty(), squared_radius(static_cast<int>(q)) == 0.0) << "query " << q;
  }
}

// Radii that vary by query, and radii that are 0 for most queries (no cell grid then: the
// tree gathers).
TEST(NearestNeighbors, FindsThePointsWithinARadiusByBruteForceForAnyThreadCount) {
  const PointList points = RandomPoints(2000, 3);
  const PointList queries = RandomPoints(50, 4);
  const NearestNeighbors search(points);
  for (bool mostly_zero : {false, true}) {
    auto squared_radius = [mostly_zero](int q) {
      return mostly_zero && q % 7 != 0 ? 0.0 : 0.01 * (1 + q % 5);
    };
    ExpectWithinByBruteForce(points, queries, search, squared_radius);
  }
}

}  // namespace
}  // namespace lpd::energy
