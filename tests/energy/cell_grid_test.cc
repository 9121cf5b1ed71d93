// The points a cell grid gathers within a radius against brute force, with the squared
// distances nanoflann's L2 adaptor computes, on clouds that strain the grid: a surface, a far
// point (the cells grow), all points equal (one cell), queries beyond the grid.
#include "energy/cell_grid.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "nanoflann_distance.h"

namespace lpd::energy {
namespace {

// Every point at a squared distance under `squared_radius`, by index, with the distance summed
// as nanoflann sums it (x, y, then z).
std::vector<std::pair<int, double>> BruteForceWithin(const PointList& points, const Point3& query,
                                                     double squared_radius) {
  std::vector<std::pair<int, double>> within;
  for (size_t i = 0; i < points.size(); ++i) {
    const double squared = NanoflannSquaredDistance(query, points[i]);
    if (squared < squared_radius) within.emplace_back(static_cast<int>(i), squared);
  }
  return within;
}

void ExpectSameAsBruteForce(const PointList& points, const CellGrid& grid, const Point3& query,
                            double squared_radius) {
  std::vector<std::pair<int, double>> gathered = {{-1, -1.0}};  // appended to, not replaced
  grid.Within(query, squared_radius, &gathered);
  ASSERT_EQ(gathered.front(), std::make_pair(-1, -1.0));
  gathered.erase(gathered.begin());
  std::sort(gathered.begin(), gathered.end());
  const auto expected = BruteForceWithin(points, query, squared_radius);
  ASSERT_EQ(gathered.size(), expected.size());
  for (size_t a = 0; a < expected.size(); ++a) {
    EXPECT_EQ(gathered[a].first, expected[a].first);
    EXPECT_EQ(gathered[a].second, expected[a].second);  // the same bits
  }
}

PointList NoisySphere(int count, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  PointList points;
  for (int i = 0; i < count; ++i) {
    const Point3 direction = Point3(normal(random), normal(random), normal(random)).normalized();
    points.push_back(direction * (1.0 + 0.01 * normal(random)));
  }
  return points;
}

TEST(CellGrid, GathersThePointsWithinARadiusByBruteForce) {
  const PointList points = NoisySphere(3000, 1);
  for (double cell_size : {0.02, 0.1, 0.5, 3.0}) {
    const CellGrid grid(points, cell_size);
    for (int q = 0; q < 3000; q += 97) {
      for (double radius : {0.0, 0.05, 0.13, 0.4, 2.5}) {
        ExpectSameAsBruteForce(points, grid, points[q], radius * radius);
      }
    }
  }
}

TEST(CellGrid, QueriesBeyondTheGridFindWhatIsInReach) {
  const PointList points = NoisySphere(2000, 2);
  const CellGrid grid(points, 0.1);
  for (const Point3& query : {Point3(3.0, 0.0, 0.0), Point3(-1.05, 0.2, 0.0),
                              Point3(0.0, 0.0, 1e200), Point3(-1e300, 1e300, 0.0)}) {
    for (double radius : {0.1, 0.3, 2.5, 5.0}) {
      ExpectSameAsBruteForce(points, grid, query, radius * radius);
    }
  }
}

TEST(CellGrid, AFarPointGrowsTheCellsAndStaysExact) {
  PointList points = NoisySphere(1000, 3);
  points.emplace_back(1e6, -1e6, 1e6);
  const CellGrid grid(points, 0.01);
  EXPECT_GT(grid.cell_size(), 0.01);  // 4,000 cells cannot span 2e6 at 0.01
  for (int q = 0; q < 1001; q += 50) ExpectSameAsBruteForce(points, grid, points[q], 0.04);
  ExpectSameAsBruteForce(points, grid, points.back(), 1e13);
}

TEST(CellGrid, EqualPointsAndAnEmptyList) {
  const PointList same(50, Point3(0.5, -0.25, 2.0));
  const CellGrid grid(same, 0.1);
  ExpectSameAsBruteForce(same, grid, Point3(0.5, -0.25, 2.0), 1e-6);
  ExpectSameAsBruteForce(same, grid, Point3(0.6, -0.25, 2.0), 0.0099);
  ExpectSameAsBruteForce(same, grid, Point3(0.6, -0.25, 2.0), 0.0101);
  const CellGrid empty(PointList{}, 0.1);
  ExpectSameAsBruteForce(PointList{}, empty, Point3::Zero(), 1.0);
}

TEST(CellGrid, RejectsACellSizeThatIsNotPositive) {
  const PointList points = NoisySphere(10, 4);
  EXPECT_THROW(CellGrid(points, 0.0), std::invalid_argument);
  EXPECT_THROW(CellGrid(points, -1.0), std::invalid_argument);
  EXPECT_THROW(CellGrid(points, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace lpd::energy
