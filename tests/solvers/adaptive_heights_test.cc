// RefitHeightsAtAdaptiveScale against a brute-force version of it (every output's nearest
// found by sorting all distances, each height field fitted by a QR decomposition of its
// design matrix in other units) on a jittered saddle and a roof with noisy heights, for 1 and
// 2 threads; and against what it must do: the saddle and a noisy plane are denoised, a roof's
// ridge is not rounded by fits across it, a flat plane stays, and points left out neither
// move nor count.
#include "solvers/adaptive_heights.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace lpd::solvers {
namespace {

struct Cloud {
  energy::PointList points, normals;
  std::vector<double> truth;  // the surface's height under each point
};

// A jittered grid of [0, 0.01 (side - 1)]^2 (no ties among distances) lifted onto the surface
// z = height(x, y), plus N(0, s^2) along z; normals: the surface's, with a seeded random sign.
template <typename Height, typename Gradient>
Cloud Surface(int side, double s, uint64_t seed, const Height& height,
              const Gradient& gradient) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> noise(0.0, s);
  std::uniform_real_distribution<double> jitter(-0.002, 0.002);
  std::bernoulli_distribution flip(0.5);
  Cloud cloud;
  for (int a = 0; a < side; ++a) {
    for (int b = 0; b < side; ++b) {
      const double x = 0.01 * a + jitter(random), y = 0.01 * b + jitter(random);
      const double z = height(x, y);
      cloud.truth.push_back(z);
      cloud.points.emplace_back(x, y, z + (s > 0.0 ? noise(random) : 0.0));
      const Eigen::Vector2d g = gradient(x, y);
      const energy::Point3 normal = energy::Point3(-g.x(), -g.y(), 1.0).normalized();
      cloud.normals.push_back(flip(random) ? -normal : normal);
    }
  }
  return cloud;
}

// The plane z = height.
Cloud Plane(int side, double s, uint64_t seed, double height) {
  return Surface(
      side, s, seed, [height](double, double) { return height; },
      [](double, double) { return Eigen::Vector2d::Zero().eval(); });
}

Cloud Saddle(int side, double s, uint64_t seed) {
  return Surface(
      side, s, seed, [](double x, double y) { return 0.8 * (x - 0.15) * (y - 0.15); },
      [](double x, double y) { return Eigen::Vector2d(0.8 * (y - 0.15), 0.8 * (x - 0.15)); });
}

double UpperMedian(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// adaptive_heights.h written out with full sorts and QR least squares, in units of 0.01.
energy::PointList BruteForce(const Cloud& cloud) {
  const int n = static_cast<int>(cloud.points.size());
  const double min_cosine = std::cos(kAdaptiveMaxAngleDegrees * M_PI / 180.0);
  std::vector<std::vector<int>> nearest(n);
  for (int i = 0; i < n; ++i) {
    std::vector<std::pair<double, int>> by_distance;
    for (int j = 0; j < n; ++j) {
      by_distance.emplace_back((cloud.points[j] - cloud.points[i]).squaredNorm(), j);
    }
    std::sort(by_distance.begin(), by_distance.end());
    for (int a = 0; a < std::min(n, kAdaptiveSearched); ++a) {
      nearest[i].push_back(by_distance[a].second);
    }
  }
  const auto normal = [&](int i) { return cloud.normals[i].normalized().eval(); };
  const auto aligned = [&](int i, int j) {
    return std::abs(normal(i).dot(normal(j))) >= min_cosine;
  };
  std::vector<double> jitters;
  for (int i = 0; i < n; ++i) {
    std::vector<double> heights;
    for (int a = 0; a < 2 * kJitterNeighbors + 1 && heights.size() < kJitterNeighbors; ++a) {
      const int j = nearest[i][a];
      if (j == i || !aligned(i, j)) continue;
      heights.push_back(std::abs(normal(i).dot(cloud.points[j] - cloud.points[i])));
    }
    if (!heights.empty()) jitters.push_back(UpperMedian(heights));
  }
  const double band = kJitterBandDeviations * 1.4826 * UpperMedian(jitters);
  const int scales = static_cast<int>(kAdaptiveScales.size());
  std::vector<std::vector<double>> intercepts(n), leverages(n);
  std::vector<double> first_variances;
  for (int i = 0; i < n; ++i) {
    const energy::Point3 nu = normal(i);
    const energy::Point3 u = nu.unitOrthogonal(), v = nu.cross(u);
    std::vector<Eigen::Vector3d> kept;  // (x, y, z), x and y in units of 0.01
    for (int j : nearest[i]) {
      const energy::Point3 d = cloud.points[j] - cloud.points[i];
      const double x = u.dot(d), y = v.dot(d), z = nu.dot(d);
      if (!aligned(i, j) || std::abs(z) > band + kBandSlope * std::hypot(x, y)) continue;
      kept.emplace_back(x / 0.01, y / 0.01, z);
    }
    for (int s = 0; s < scales && kAdaptiveScales[s] <= static_cast<int>(kept.size()); ++s) {
      const int m = kAdaptiveScales[s];
      Eigen::MatrixXd design(m, 6);
      Eigen::VectorXd heights(m);
      for (int a = 0; a < m; ++a) {
        const double x = kept[a].x(), y = kept[a].y();
        design.row(a) << 1.0, x, y, x * x, x * y, y * y;
        heights[a] = kept[a].z();
      }
      const Eigen::VectorXd beta = design.colPivHouseholderQr().solve(heights);
      intercepts[i].push_back(beta[0]);
      leverages[i].push_back((design.transpose() * design).inverse()(0, 0));
      if (s == 0) first_variances.push_back((heights - design * beta).squaredNorm() / (m - 6));
    }
  }
  const double g = UpperMedian(first_variances);
  energy::PointList result = cloud.points;
  for (int i = 0; i < n; ++i) {
    double low = -std::numeric_limits<double>::infinity();
    double high = std::numeric_limits<double>::infinity();
    double chosen = 0.0;
    for (size_t s = 0; s < intercepts[i].size(); ++s) {
      const double half = kIntervalHalfWidth * std::sqrt(g * leverages[i][s]);
      low = std::max(low, intercepts[i][s] - half);
      high = std::min(high, intercepts[i][s] + half);
      if (low > high) break;
      chosen = intercepts[i][s];
    }
    result[i] += chosen * normal(i);
  }
  return result;
}

double MeanAbsError(const Cloud& cloud, const energy::PointList& points,
                    const std::vector<int>& rows) {
  double sum = 0.0;
  for (int i : rows) sum += std::abs(points[i].z() - cloud.truth[i]);
  return sum / rows.size();
}

// The step on every point of `cloud`, all movable.
energy::PointList RefitAll(const Cloud& cloud, int threads) {
  return RefitHeightsAtAdaptiveScale(cloud.points, cloud.normals,
                                     std::vector<uint8_t>(cloud.points.size(), 1), threads);
}

std::vector<int> AllRows(const Cloud& cloud) {
  std::vector<int> rows(cloud.points.size());
  for (size_t i = 0; i < rows.size(); ++i) rows[i] = static_cast<int>(i);
  return rows;
}

// A roof z = 0.5 |x - 0.15| (its faces' normals 53 degrees apart), heights N(0, s^2).
Cloud Roof(int side, double s, uint64_t seed) {
  return Surface(
      side, s, seed, [](double x, double) { return 0.5 * std::abs(x - 0.15); },
      [](double x, double) { return Eigen::Vector2d(x < 0.15 ? -0.5 : 0.5, 0.0); });
}

TEST(RefitHeightsAtAdaptiveScale, MatchesTheBruteForceOnANoisySaddleAndRoof) {
  for (const Cloud& cloud : {Saddle(30, 0.003, 7), Roof(30, 0.002, 5)}) {
    const energy::PointList expected = BruteForce(cloud);
    int moved = 0;
    for (int threads : {1, 2}) {
      SCOPED_TRACE(threads);
      const energy::PointList refitted = RefitAll(cloud, threads);
      for (size_t i = 0; i < refitted.size(); ++i) {
        // Estimates are stored as floats: agreement to about 1e-7 of the heights moved.
        ASSERT_NEAR((refitted[i] - expected[i]).norm(), 0.0, 1e-8) << "point " << i;
        moved += refitted[i] != cloud.points[i];
      }
    }
    EXPECT_GT(moved, 1500);
  }
}

TEST(RefitHeightsAtAdaptiveScale, DenoisesASaddle) {
  const Cloud cloud = Saddle(30, 0.003, 7);
  const energy::PointList refitted = RefitAll(cloud, 2);
  EXPECT_LT(MeanAbsError(cloud, refitted, AllRows(cloud)),
            0.5 * MeanAbsError(cloud, cloud.points, AllRows(cloud)));
}

TEST(RefitHeightsAtAdaptiveScale, AveragesANoisyPlaneOverTheWidestScale) {
  const Cloud cloud = Plane(30, 0.002, 11, 0.0);
  const energy::PointList refitted = RefitAll(cloud, 2);
  // A fit over 256 of 900 iid heights leaves about sqrt(L_256) ~ 0.1-0.2 of the deviation
  // at the centre (more at the border, where the fit extrapolates).
  EXPECT_LT(MeanAbsError(cloud, refitted, AllRows(cloud)),
            0.3 * MeanAbsError(cloud, cloud.points, AllRows(cloud)));
}

TEST(RefitHeightsAtAdaptiveScale, DoesNotRoundARidge) {
  const Cloud cloud = Roof(30, 0.002, 5);
  const energy::PointList refitted = RefitAll(cloud, 2);
  std::vector<int> ridge;
  for (size_t i = 0; i < cloud.points.size(); ++i) {
    if (std::abs(cloud.points[i].x() - 0.15) < 0.02) ridge.push_back(static_cast<int>(i));
  }
  ASSERT_GT(ridge.size(), 80u);
  // Fits across the ridge would lift its points by the roof's rise over the fit's radius
  // (0.5 x 0.05 at 256 neighbours, ten times the noise); within a face they denoise.
  EXPECT_LT(MeanAbsError(cloud, refitted, ridge), MeanAbsError(cloud, cloud.points, ridge));
  EXPECT_LT(MeanAbsError(cloud, refitted, AllRows(cloud)),
            0.6 * MeanAbsError(cloud, cloud.points, AllRows(cloud)));
}

TEST(RefitHeightsAtAdaptiveScale, LeavesAFlatPlaneWhereItIs) {
  const Cloud cloud = Plane(20, 0.0, 3, 0.25);
  const energy::PointList refitted = RefitAll(cloud, 2);
  for (size_t i = 0; i < refitted.size(); ++i) {
    EXPECT_NEAR((refitted[i] - cloud.points[i]).norm(), 0.0, 1e-12) << "point " << i;
  }
}

TEST(RefitHeightsAtAdaptiveScale, PointsLeftOutNeitherMoveNorCount) {
  Cloud cloud = Saddle(24, 0.002, 9);
  const int lifted = 300;
  cloud.points[lifted].z() += 0.004;
  // The run without the point at all.
  Cloud without = cloud;
  without.points.erase(without.points.begin() + lifted);
  without.normals.erase(without.normals.begin() + lifted);
  const energy::PointList expected = RefitAll(without, 2);
  for (int variant = 0; variant < 2; ++variant) {
    SCOPED_TRACE(variant);
    Cloud left_out = cloud;
    std::vector<uint8_t> movable(cloud.points.size(), 1);
    if (variant == 0) {
      movable[lifted] = 0;
    } else {
      left_out.normals[lifted].setZero();
    }
    const energy::PointList refitted =
        RefitHeightsAtAdaptiveScale(left_out.points, left_out.normals, movable, 2);
    EXPECT_EQ(refitted[lifted], cloud.points[lifted]);
    for (size_t i = 0, e = 0; i < refitted.size(); ++i) {
      if (static_cast<int>(i) == lifted) continue;
      EXPECT_NEAR((refitted[i] - expected[e++]).norm(), 0.0, 1e-15) << "point " << i;
    }
  }
  // Taking part, the lifted point moves back toward the saddle.
  const energy::PointList refitted = RefitAll(cloud, 2);
  EXPECT_LT(std::abs(refitted[lifted].z() - cloud.truth[lifted]),
            0.5 * std::abs(cloud.points[lifted].z() - cloud.truth[lifted]));
}

}  // namespace
}  // namespace lpd::solvers
