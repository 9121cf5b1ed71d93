// ScatterSum against Eigen's sum of outer products over the same seeded vectors: the same
// bits, the full symmetric matrix.
#include "energy/scatter_sum.h"

#include <random>

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

}  // namespace
}  // namespace lpd::energy
