// The k nearest that KnnByRadius finds from a cell grid alone (even spacing's later rounds)
// against a brute-force sort by (squared distance, index): with guesses too small (a miss
// grows on the grid), none, and too large, with fewer points than k, with repeated points.
#include "energy/knn_by_radius.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "nanoflann_distance.h"

namespace lpd::energy {
namespace {

// The min(k, n) nearest to `query` by (squared distance, index), the distance summed as
// nanoflann sums it.
std::vector<std::pair<double, int>> BruteForceNearest(const PointList& points,
                                                      const Point3& query, int k) {
  std::vector<std::pair<double, int>> all;
  for (size_t i = 0; i < points.size(); ++i) {
    all.emplace_back(NanoflannSquaredDistance(query, points[i]), static_cast<int>(i));
  }
  std::sort(all.begin(), all.end());
  all.resize(std::min<size_t>(k, all.size()));
  return all;
}

void ExpectBruteForce(const PointList& points, const CellGrid& grid, KnnByRadius* search,
                      const Point3& query, int k) {
  std::vector<int> nearest(k, -1);
  std::vector<double> squared(k, -1.0);
  const int found = search->Search(nullptr, &grid, query, k, nearest.data(), squared.data());
  const auto expected = BruteForceNearest(points, query, k);
  ASSERT_EQ(found, static_cast<int>(expected.size()));
  for (int a = 0; a < found; ++a) {
    EXPECT_EQ(nearest[a], expected[a].second) << "neighbour " << a;
    EXPECT_EQ(squared[a], expected[a].first) << "neighbour " << a;  // the same bits
  }
}

PointList NoisyPlane(int count, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 0.002);
  PointList points;
  for (int i = 0; i < count; ++i) {
    points.emplace_back(uniform(random), uniform(random), normal(random));
  }
  return points;
}

TEST(KnnByRadius, OnAGridAloneAnyGuessGivesTheNearestByDistanceThenIndex) {
  const PointList points = NoisyPlane(3000, 5);
  constexpr int kNeighbors = 11;
  const double spacing = 1.0 / std::sqrt(3000.0);
  for (double cell_size : {0.3 * spacing, spacing, 4.0 * spacing}) {
    const CellGrid grid(points, cell_size);
    for (double guess : {0.0, 1e-12, spacing * spacing, 100.0 * spacing * spacing, 10.0}) {
      KnnByRadius search;
      for (int q = 0; q < 3000; q += 37) {
        search.Guess(guess);  // each query from this guess, not the last query's
        ExpectBruteForce(points, grid, &search, points[q], kNeighbors);
      }
    }
    KnnByRadius chained;  // the guess carried from query to query
    for (int q = 0; q < 3000; q += 7) ExpectBruteForce(points, grid, &chained, points[q], 40);
  }
}

TEST(KnnByRadius, OnAGridAloneFewerPointsThanKGivesThemAll) {
  const PointList points = NoisyPlane(9, 6);
  const CellGrid grid(points, 0.01);
  KnnByRadius search;
  search.Guess(1e-6);
  ExpectBruteForce(points, grid, &search, points[4], 11);
  ExpectBruteForce(points, grid, &search, Point3(50.0, -3.0, 2.0), 11);  // far beyond the grid
}

TEST(KnnByRadius, OnAGridAloneRepeatedPointsComeByIndex) {
  PointList points = NoisyPlane(200, 7);
  for (int copy = 0; copy < 15; ++copy) points.push_back(points[10]);
  const CellGrid grid(points, 0.02);
  KnnByRadius search;
  ExpectBruteForce(points, grid, &search, points[10], 11);  // 16 at distance 0: the first 11
  ExpectBruteForce(points, grid, &search, points[10], 30);
}

}  // namespace
}  // namespace lpd::energy
