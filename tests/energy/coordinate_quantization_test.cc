// The rounding noise of a coordinate grid, against its closed form q / sqrt(12).
#include "energy/coordinate_quantization.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace lpd::energy {
namespace {

PointList RandomPoints(int count, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  PointList points;
  for (int i = 0; i < count; ++i) points.emplace_back(uniform(random), uniform(random), uniform(random));
  return points;
}

TEST(QuantizationNoise, PointsOnAGridCarryItsRoundingNoise) {
  // Steps 0.01, 0.02 and 0.05 on the three axes, 5000 points on [-1, 1]^3: every pair of
  // neighbouring levels occurs, so the smallest gaps are the steps.
  const double steps[3] = {0.01, 0.02, 0.05};
  PointList points = RandomPoints(5000, 3);
  for (Point3& p : points) {
    for (int a = 0; a < 3; ++a) p[a] = std::round(p[a] / steps[a]) * steps[a];
  }
  const double expected =
      std::sqrt((0.01 * 0.01 + 0.02 * 0.02 + 0.05 * 0.05) / 3.0 / 12.0);
  EXPECT_NEAR(QuantizationNoise(points), expected, 1e-12);
  // Shifted off the origin the steps stay the same (to the doubles' rounding).
  for (Point3& p : points) p += Point3(1000.0, -250.0, 7.0);
  EXPECT_NEAR(QuantizationNoise(points), expected, 1e-9);
  // Scaled by 1e300 or 1e-300, the result scales with them: no overflow, no underflow.
  for (const double scale : {1e300, 1e-300}) {
    PointList scaled = points;
    for (Point3& p : scaled) p *= scale;
    EXPECT_NEAR(QuantizationNoise(scaled) / scale, expected, 1e-6) << scale;
  }
}

TEST(QuantizationNoise, CoordinatesOffAGridGiveAlmostNothing) {
  // 5000 uniform values on an interval of 2: neighbouring gaps are exponential with mean
  // 2 / 5000, so the smallest is about 2 / 5000^2 = 8e-8.
  EXPECT_LT(QuantizationNoise(RandomPoints(5000, 4)), 1e-6);
}

TEST(QuantizationNoise, FewerThanTwoPointsOrOneValueGiveZero) {
  EXPECT_EQ(QuantizationNoise({}), 0.0);
  EXPECT_EQ(QuantizationNoise({Point3(1, 2, 3)}), 0.0);
  EXPECT_EQ(QuantizationNoise({Point3(1, 2, 3), Point3(1, 2, 3)}), 0.0);
}

}  // namespace
}  // namespace lpd::energy
