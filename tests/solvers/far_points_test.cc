// Far points: the test against a brute-force reading of its rule, no false alarms on clouds
// whose density falls off, and the pipeline unchanged for the other points.
#include "solvers/far_points.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "lpd/presets.h"
#include "solvers/denoise_point_set.h"
#include "test_problems.h"

namespace lpd::solvers {
namespace {

using energy::Point3;
using energy::PointList;

// The rule read literally: full sorts instead of selection.
std::vector<uint8_t> BruteForceFar(const PointList& points, const FarPointOptions& options) {
  const size_t n = points.size();
  Point3 median;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> values;
    for (const Point3& p : points) values.push_back(p[axis]);
    std::sort(values.begin(), values.end());
    median[axis] = values[n / 2];
  }
  std::vector<double> distances;
  for (const Point3& p : points) distances.push_back((p - median).norm());
  std::vector<double> sorted = distances;
  std::sort(sorted.begin(), sorted.end());
  const double radius = sorted[std::min(n - 1, static_cast<size_t>(options.bulk_fraction * n))];
  std::vector<uint8_t> far(n);
  for (size_t i = 0; i < n; ++i) far[i] = distances[i] > options.factor * radius;
  return far;
}

TEST(FarPoints, AgreesWithTheBruteForceRule) {
  std::mt19937_64 random(5);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> exponent(0.0, 12.0);
  for (int trial = 0; trial < 20; ++trial) {
    PointList points = testing::NoisyPlane(500 + 37 * trial, 0.01, trial);
    for (int f = 0; f < trial; ++f) {
      points.push_back(Point3(normal(random), normal(random), normal(random)).normalized() *
                       std::pow(10.0, exponent(random)));
    }
    const FarPointOptions options;
    EXPECT_EQ(FlagFarPoints(points, options), BruteForceFar(points, options)) << trial;
  }
}

TEST(FarPoints, NoneOnCloudsWhoseDensityFallsOffWithRange) {
  // A scan of the ground around a scanner: radii log-uniform from 0.1 to 50 (the density
  // falls as 1 / r^2), and a noisy plane.
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  PointList ground;
  for (int i = 0; i < 20000; ++i) {
    const double r = 0.1 * std::pow(500.0, uniform(random));
    const double angle = 2.0 * M_PI * uniform(random);
    ground.emplace_back(r * std::cos(angle), r * std::sin(angle), 0.01 * uniform(random));
  }
  const FarPointOptions options;
  for (const PointList& cloud : {ground, testing::NoisyPlane(3000, 0.02, 1)}) {
    const std::vector<uint8_t> far = FlagFarPoints(cloud, options);
    EXPECT_EQ(std::count(far.begin(), far.end(), 1), 0);
  }
  FarPointOptions off = options;
  off.factor = 0.0;
  PointList with_far = ground;
  with_far.emplace_back(1e9, 0.0, 0.0);
  const std::vector<uint8_t> none = FlagFarPoints(with_far, off);
  EXPECT_EQ(std::count(none.begin(), none.end(), 1), 0);
}

// The other points' result is the one without the far points, bit for bit: one far point,
// 0.1% and 1% of the points, from 1e3 to 1e12 times the extent.
TEST(FarPoints, LeaveTheOtherPointsResultAsWithoutThem) {
  const PointList clean = testing::NoisyPlane(2000, 0.003, 7);
  DenoiseOptions options = PresetOptions(Preset::kDefault);
  options.settings.num_threads = 2;
  options.minimizer.max_iterations = 15;
  const DenoiseResult reference = DenoisePointSet(clean, options);
  for (const int count : {1, 2, 20}) {
    for (const double offset : {1e3, 1e6, 1e12}) {
      PointList points = clean;
      std::vector<int> clean_rows;
      for (int f = 0; f < count; ++f) points.emplace_back(offset, -offset * f, 0.5 * offset);
      // Spread the far points through the input, as a scan would have them.
      std::mt19937_64 random(count);
      std::shuffle(points.begin(), points.end(), random);
      for (size_t i = 0; i < points.size(); ++i) {
        if (points[i].x() < offset / 2) clean_rows.push_back(static_cast<int>(i));
      }
      PointList clean_order;
      for (int i : clean_rows) clean_order.push_back(points[i]);
      const DenoiseResult alone = DenoisePointSet(clean_order, options);
      const DenoiseResult result = DenoisePointSet(points, options);
      EXPECT_EQ(result.num_far, count);
      EXPECT_EQ(result.num_removed, alone.num_removed + count);
      for (size_t r = 0; r < clean_rows.size(); ++r) {
        const int i = clean_rows[r];
        ASSERT_EQ(result.projected[i], alone.projected[r]) << "offset " << offset;
        ASSERT_EQ(result.kept[i], alone.kept[r]);
      }
      for (size_t i = 0; i < points.size(); ++i) {
        if (points[i].x() < offset / 2) continue;
        EXPECT_TRUE(result.indicators.is_outlier[i]);
        EXPECT_FALSE(result.kept[i]);
        EXPECT_EQ(result.projected[i], points[i]);
      }
    }
  }
  EXPECT_EQ(reference.num_far, 0);
}

}  // namespace
}  // namespace lpd::solvers
