// The isolation test against a brute-force m-th neighbour distance, and on a sampled plane
// with far points: it flags exactly those, at any scale, and only among kept points.
#include "solvers/isolated_points.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace lpd::solvers {
namespace {

// A 60 x 60 jittered grid on the plane z = 0, spacing 1, then `far` points 30-50 units away.
energy::PointList PlaneWithFarPoints(int far, uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2), away(30.0, 50.0);
  energy::PointList points;
  for (int x = 0; x < 60; ++x) {
    for (int y = 0; y < 60; ++y) points.emplace_back(x + jitter(random), y + jitter(random), 0.0);
  }
  for (int i = 0; i < far; ++i) points.emplace_back(10.0 * i, 30.0, away(random));
  return points;
}

double MedianOf(std::vector<double> values) {
  const size_t half = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + half, values.end());
  return values[half];
}

// The m-th neighbour distance by sorting all distances, and the rule of the header.
std::vector<uint8_t> BruteForce(const energy::PointList& points, const std::vector<uint8_t>& kept,
                                int m, double factor) {
  const size_t n = points.size();
  std::vector<double> radius(n, 0.0), kept_radii;
  std::vector<std::vector<size_t>> neighbors(n);
  for (size_t i = 0; i < n; ++i) {
    if (!kept[i]) continue;
    std::vector<std::pair<double, size_t>> by_distance;
    for (size_t j = 0; j < n; ++j) {
      if (kept[j] && j != i) by_distance.emplace_back((points[i] - points[j]).norm(), j);
    }
    std::sort(by_distance.begin(), by_distance.end());
    radius[i] = by_distance[m - 1].first;
    for (int a = 0; a < m; ++a) neighbors[i].push_back(by_distance[a].second);
    kept_radii.push_back(radius[i]);
  }
  const double global = MedianOf(kept_radii);
  std::vector<uint8_t> isolated(n, 0);
  for (size_t i = 0; i < n; ++i) {
    if (!kept[i]) continue;
    std::vector<double> around;
    for (size_t j : neighbors[i]) around.push_back(radius[j]);
    isolated[i] = radius[i] > factor * global && radius[i] > factor * MedianOf(around);
  }
  return isolated;
}

TEST(FlagIsolatedPoints, AgreesWithABruteForceSearch) {
  // Clusters of different density, so that radii spread around the median.
  std::mt19937 random(7);
  std::normal_distribution<double> gauss;
  energy::PointList points;
  for (int c = 0; c < 6; ++c) {
    const double width = 0.2 * (c + 1);
    for (int i = 0; i < 80; ++i) {
      points.emplace_back(10.0 * c + width * gauss(random), width * gauss(random), 0.0);
    }
  }
  std::vector<uint8_t> kept(points.size(), 1);
  for (size_t i = 0; i < points.size(); i += 7) kept[i] = 0;
  IsolationOptions options;
  options.neighbors = 10;
  for (double factor : {1.2, 1.5, 2.0}) {
    options.radius_factor = factor;
    const std::vector<uint8_t> isolated = FlagIsolatedPoints(points, kept, options, 2);
    EXPECT_EQ(isolated, BruteForce(points, kept, options.neighbors, factor)) << factor;
    EXPECT_GT(std::count(isolated.begin(), isolated.end(), 1), 0) << factor;
  }
}

TEST(FlagIsolatedPoints, FlagsExactlyTheFarPointsAtAnyScale) {
  const energy::PointList points = PlaneWithFarPoints(4, 3);
  const std::vector<uint8_t> kept(points.size(), 1);
  const IsolationOptions options;
  for (double scale : {1e-6, 1.0, 1e9}) {
    energy::PointList scaled = points;
    for (energy::Point3& p : scaled) p *= scale;
    const std::vector<uint8_t> isolated = FlagIsolatedPoints(scaled, kept, options, 2);
    for (size_t i = 0; i < points.size(); ++i) {
      EXPECT_EQ(isolated[i], i >= 3600 ? 1 : 0) << "point " << i << " at scale " << scale;
    }
  }
}

TEST(FlagIsolatedPoints, ARegionSampledTenTimesSparserKeepsItsPoints) {
  // Uniform samples, 8 per unit area for x < 30 and 0.8 for x >= 30: the 40th neighbour lies
  // at sqrt(40 / (pi density)), 1.26 and 3.99, so about half of the sparse points are beyond
  // 3x the global median (1.26) and only the comparison with their neighbours spares them.
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  energy::PointList points;
  for (int i = 0; i < 14400; ++i) {
    points.emplace_back(30.0 * unit(random), 60.0 * unit(random), 0.0);
  }
  for (int i = 0; i < 1440; ++i) {
    points.emplace_back(30.0 + 30.0 * unit(random), 60.0 * unit(random), 0.0);
  }
  points.emplace_back(15.0, 30.0, 40.0);  // and one far point
  const std::vector<uint8_t> kept(points.size(), 1);
  const std::vector<uint8_t> isolated = FlagIsolatedPoints(points, kept, {}, 2);
  EXPECT_EQ(isolated.back(), 1);
  EXPECT_EQ(std::count(isolated.begin(), isolated.end(), 1), 1);
}

TEST(FlagIsolatedPoints, OnlyKeptPointsCountAndAreFlagged) {
  energy::PointList points = PlaneWithFarPoints(1, 5);
  const energy::Point3 far = points.back();
  // 50 removed points around the far one: they neither hide it nor get flagged themselves.
  for (int i = 0; i < 50; ++i) points.push_back(far + energy::Point3(0.01 * i, 0.0, 0.0));
  std::vector<uint8_t> kept(points.size(), 1);
  std::fill(kept.begin() + 3601, kept.end(), 0);
  const std::vector<uint8_t> isolated = FlagIsolatedPoints(points, kept, {}, 2);
  EXPECT_EQ(isolated[3600], 1);
  EXPECT_EQ(std::count(isolated.begin(), isolated.end(), 1), 1);
}

TEST(FlagIsolatedPoints, OffOrTooFewPointsFlagsNothing) {
  const energy::PointList points = PlaneWithFarPoints(4, 9);
  std::vector<uint8_t> kept(points.size(), 1);
  IsolationOptions off;
  off.radius_factor = 0.0;
  const std::vector<uint8_t> none(points.size(), 0);
  EXPECT_EQ(FlagIsolatedPoints(points, kept, off, 2), none);
  std::fill(kept.begin() + 30, kept.end(), 0);  // 30 kept points, fewer than 40 + 1
  EXPECT_EQ(FlagIsolatedPoints(points, kept, {}, 2), none);

  std::string error;
  IsolationOptions bad;
  bad.radius_factor = 0.5;
  EXPECT_FALSE(bad.IsValid(&error));
  EXPECT_NE(error.find("isolation_factor"), std::string::npos);
}

}  // namespace
}  // namespace lpd::solvers
