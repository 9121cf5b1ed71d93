// SmoothHeights against a brute-force version of its rounds (every point's nearest found by
// sorting all distances) on a jittered plane, for 1 and 2 threads; and against closed forms:
// a flat plane and an edge's faces stay put exactly, one output off a flat layer does not
// move it, a sphere keeps its radius where rounds at lambda alone shrink it, points left out
// neither move nor count.
#include "solvers/height_smoothing.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>

#include <gtest/gtest.h>

namespace lpd::solvers {
namespace {

struct Cloud {
  energy::PointList points, normals;
};

// A jittered grid of the unit square in z = 0 (no ties among distances), heights N(0, s^2),
// normals +-z in a seeded random mix.
Cloud JitteredPlane(int side, double s, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> height(0.0, s);
  std::uniform_real_distribution<double> jitter(-0.002, 0.002);
  std::bernoulli_distribution flip(0.5);
  Cloud cloud;
  for (int a = 0; a < side; ++a) {
    for (int b = 0; b < side; ++b) {
      cloud.points.emplace_back(0.01 * a + jitter(random), 0.01 * b + jitter(random),
                                s > 0.0 ? height(random) : 0.0);
      cloud.normals.emplace_back(0.0, 0.0, flip(random) ? -1.0 : 1.0);
    }
  }
  return cloud;
}

// The rounds of height_smoothing.h written out: N_i from a full sort of the distances, each
// round's medians from the positions of the round before, factors `first` then `second`.
energy::PointList BruteForce(const Cloud& cloud, double band, int pairs, double first,
                             double second) {
  const int n = static_cast<int>(cloud.points.size());
  const double min_cosine = std::cos(kHeightMaxAngleDegrees * M_PI / 180.0);
  std::vector<std::vector<int>> neighbors(n);
  for (int i = 0; i < n; ++i) {
    std::vector<std::pair<double, int>> by_distance;
    for (int j = 0; j < n; ++j) {
      by_distance.emplace_back((cloud.points[j] - cloud.points[i]).squaredNorm(), j);
    }
    std::sort(by_distance.begin(), by_distance.end());
    const energy::Point3& normal = cloud.normals[i];
    for (int a = 0; a <= kHeightNeighbors && a < n; ++a) {
      const int j = by_distance[a].second;
      if (std::abs(normal.dot(cloud.normals[j])) < min_cosine) continue;
      if (!(std::abs(normal.dot(cloud.points[j] - cloud.points[i])) < band)) continue;
      neighbors[i].push_back(j);
    }
  }
  energy::PointList current = cloud.points;
  for (int round = 0; round < 2 * pairs; ++round) {
    const double factor = round % 2 == 0 ? first : second;
    energy::PointList next = current;
    for (int i = 0; i < n; ++i) {
      std::vector<double> heights;
      for (int j : neighbors[i]) heights.push_back(cloud.normals[i].dot(current[j] - current[i]));
      std::sort(heights.begin(), heights.end());
      const size_t m = heights.size();
      const double median = m % 2 ? heights[m / 2] : 0.5 * (heights[m / 2 - 1] + heights[m / 2]);
      next[i] += factor * median * cloud.normals[i];
    }
    current = next;
  }
  return current;
}

double RmsHeight(const energy::PointList& points) {
  double sum = 0.0;
  for (const auto& p : points) sum += p.z() * p.z();
  return std::sqrt(sum / points.size());
}

TEST(SmoothHeights, MatchesTheRoundsByBruteForceAndDampsTheJitter) {
  const double s = 0.002;
  const Cloud plane = JitteredPlane(30, s, 3);
  const std::vector<uint8_t> movable(plane.points.size(), 1);
  // A band of two deviations leaves out some neighbours (independent heights differ by up
  // to 2.8 s), one of ten none.
  for (double band : {2.0 * s, 10.0 * s}) {
    const energy::PointList expected = BruteForce(plane, band, 2, kTaubinLambda, kTaubinMu);
    for (int threads : {1, 2}) {
      const energy::PointList smoothed =
          SmoothHeights(plane.points, plane.normals, movable, band, 2, threads);
      for (size_t i = 0; i < smoothed.size(); ++i) {
        EXPECT_NEAR((smoothed[i] - expected[i]).norm(), 0.0, 1e-15);
        EXPECT_EQ(smoothed[i].x(), plane.points[i].x());  // along the normal only
      }
      // Independent heights, all neighbours counted: two pairs take the RMS height from
      // 2.01e-3 to 1.12e-3 (four rounds at lambda alone, which also flatten a curved
      // surface, to 0.49e-3).
      if (band > 2.0 * s) {
        EXPECT_LT(RmsHeight(smoothed), 0.6 * RmsHeight(plane.points));
      }
    }
  }
}

TEST(SmoothHeights, LeavesAFlatPlaneAndAnEdgesFacesWhereTheyAre) {
  // Face A: z = 0 (normals +-z); face B: x = 0, z > 0 (normals +-x), meeting at an edge.
  Cloud cloud = JitteredPlane(20, 0.0, 4);
  const size_t on_a = cloud.points.size();
  for (int a = 1; a <= 10; ++a) {
    for (int b = 0; b < 20; ++b) {
      cloud.points.emplace_back(0.0, 0.01 * b + 0.003, 0.01 * a);
      cloud.normals.emplace_back(b % 2 ? 1.0 : -1.0, 0.0, 0.0);
    }
  }
  const std::vector<uint8_t> movable(cloud.points.size(), 1);
  const energy::PointList smoothed =
      SmoothHeights(cloud.points, cloud.normals, movable, 0.05, 2, 2);
  for (size_t i = 0; i < smoothed.size(); ++i) {
    if (i < on_a) {
      EXPECT_EQ(smoothed[i].z(), 0.0);
    } else {
      EXPECT_EQ(smoothed[i].x(), 0.0);
    }
  }
}

TEST(SmoothHeights, AnOutputOffItsLayerDoesNotPullTheLayer) {
  // A flat layer with one output 0.01 above it (a thin part's point left between its sides):
  // the median height of every layer point's neighbours stays 0, where their mean would not.
  Cloud cloud = JitteredPlane(20, 0.0, 6);
  const size_t off = 210;
  cloud.points[off].z() = 0.01;
  const std::vector<uint8_t> movable(cloud.points.size(), 1);
  const energy::PointList smoothed =
      SmoothHeights(cloud.points, cloud.normals, movable, 0.05, 2, 2);
  for (size_t i = 0; i < smoothed.size(); ++i) {
    if (i != off) {
      EXPECT_EQ(smoothed[i].z(), 0.0);
    }
  }
  EXPECT_LT(std::abs(smoothed[off].z()), 0.01);  // it moves toward the layer
}

TEST(SmoothHeights, KeepsASphereRoundWhereRoundsAtLambdaAloneShrinkIt) {
  // 2,000 points on the unit sphere (a Fibonacci lattice), radial normals.
  Cloud sphere;
  const int n = 2000;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n;
    const double r = std::sqrt(1.0 - z * z);
    sphere.points.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
    sphere.normals.push_back(sphere.points.back());
  }
  const std::vector<uint8_t> movable(n, 1);
  const double band = 0.05;  // the 8 nearest lie 0.003-0.009 below the tangent planes
  auto mean_radius_change = [](const energy::PointList& points) {
    double sum = 0.0;
    for (const auto& p : points) sum += p.norm() - 1.0;
    return sum / points.size();
  };
  const double taubin =
      mean_radius_change(SmoothHeights(sphere.points, sphere.normals, movable, band, 2, 2));
  const double lambda_only =
      mean_radius_change(BruteForce(sphere, band, 2, kTaubinLambda, kTaubinLambda));
  // Measured: +3.6e-4 against -9.6e-3 for four rounds at lambda.
  EXPECT_LT(lambda_only, -1e-3);
  EXPECT_LT(std::abs(taubin), 0.1 * std::abs(lambda_only));
}

TEST(SmoothHeights, PointsLeftOutNeitherMoveNorCount) {
  const Cloud plane = JitteredPlane(20, 0.002, 5);
  std::vector<uint8_t> movable(plane.points.size(), 1);
  energy::PointList normals = plane.normals;
  energy::PointList points = plane.points;
  // Every third point is an outlier far above, every seventh has no normal.
  for (size_t i = 0; i < points.size(); i += 3) {
    movable[i] = 0;
    points[i].z() = 1.0;
  }
  for (size_t i = 1; i < points.size(); i += 7) normals[i].setZero();
  const energy::PointList smoothed = SmoothHeights(points, normals, movable, 0.004, 2, 2);
  Cloud kept;
  std::vector<size_t> rows;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!movable[i] || normals[i].squaredNorm() == 0.0) {
      EXPECT_EQ(smoothed[i], points[i]);
    } else {
      kept.points.push_back(points[i]);
      kept.normals.push_back(normals[i]);
      rows.push_back(i);
    }
  }
  const energy::PointList expected = BruteForce(kept, 0.004, 2, kTaubinLambda, kTaubinMu);
  for (size_t r = 0; r < rows.size(); ++r) {
    EXPECT_NEAR((smoothed[rows[r]] - expected[r]).norm(), 0.0, 1e-15);
  }
}

}  // namespace
}  // namespace lpd::solvers
