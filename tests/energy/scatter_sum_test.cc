// ScatterSum against Eigen's sum of outer products over the same seeded vectors: the same
// bits, the full symmetric matrix. LeastSquaresPlaneNormal against a plane's closed-form
// normal.
#include "energy/scatter_sum.h"

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

namespace lpd::energy {
namespace {

TEST(ScatterSum, HoldsTheSameBitsAsEigensSumOfOuterProducts) {
  std::mt19937_64 random(7);
  std::normal_distribution<double> value(0.0, 1.0);
  for (int count : {0, 1, 3, 261}) {
    ScatterSum sum;
    Eigen::Matrix3d expected = Eigen::Matrix3d::Zero();
    for (int a = 0; a < count; ++a) {
      // Scales far apart, so that a different order of the additions would show.
      const Eigen::Vector3d d(1e3 * value(random), value(random), 1e-3 * value(random));
      sum.Add(d);
      expected += d * d.transpose();
    }
    const Eigen::Matrix3d matrix = sum.Matrix();
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(matrix(r, c), expected(r, c)) << count << " vectors, entry " << r << c;
      }
    }
  }
}

TEST(LeastSquaresPlaneNormal, IsTheNormalOfThePlaneThePointsLieOn) {
  // Points on z = 0.3 x - 0.2 y + 0.5, spread over a square: the normal is (-0.3, 0.2, 1)
  // normalized (either sign), the mean the points' mean.
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::vector<Eigen::Vector3d> points(50);
  Eigen::Vector3d expected_mean = Eigen::Vector3d::Zero();
  for (auto& p : points) {
    const double x = coordinate(random), y = coordinate(random);
    p = {x, y, 0.3 * x - 0.2 * y + 0.5};
    expected_mean += p / points.size();
  }
  Eigen::Vector3d mean;
  const Eigen::Vector3d normal = LeastSquaresPlaneNormal(
      static_cast<int>(points.size()), [&](int a) { return points[a]; }, &mean);
  const Eigen::Vector3d expected = Eigen::Vector3d(-0.3, 0.2, 1.0).normalized();
  EXPECT_NEAR(std::abs(normal.dot(expected)), 1.0, 1e-12);
  EXPECT_NEAR(normal.norm(), 1.0, 1e-12);
  EXPECT_LT((mean - expected_mean).norm(), 1e-12);
}

}  // namespace
}  // namespace lpd::energy
