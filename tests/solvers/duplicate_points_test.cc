// Repeated points: the first occurrences against a brute-force search, and a cloud given
// twice over denoised exactly as the single copy.
#include "solvers/duplicate_points.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "lpd/presets.h"
#include "solvers/denoise_point_set.h"
#include "test_problems.h"

namespace lpd::solvers {
namespace {

using energy::Point3;
using energy::PointList;

TEST(DuplicatePoints, FirstOccurrencesAgreeWithBruteForce) {
  std::mt19937_64 random(3);
  std::uniform_int_distribution<int> cell(0, 4);  // 125 positions: many repeats
  PointList points;
  for (int i = 0; i < 600; ++i) points.emplace_back(cell(random), cell(random), 0.5 * cell(random));
  points.emplace_back(0.0, -0.0, 0.0);  // -0 equals 0
  points.emplace_back(std::numeric_limits<double>::quiet_NaN(), 1.0, 1.0);
  points.emplace_back(std::numeric_limits<double>::quiet_NaN(), 1.0, 1.0);
  points.emplace_back(std::numeric_limits<double>::infinity(), 1.0, 1.0);
  points.emplace_back(std::numeric_limits<double>::infinity(), 1.0, 1.0);
  const std::vector<int> first = FirstOccurrences(points);
  for (size_t i = 0; i < points.size(); ++i) {
    int expected = static_cast<int>(i);
    if (points[i].allFinite()) {
      for (size_t j = 0; j < i; ++j) {
        if (points[j] == points[i]) {
          expected = static_cast<int>(j);
          break;
        }
      }
    }
    ASSERT_EQ(first[i], expected) << i;
  }
  EXPECT_NE(first[600], 600);  // (0, -0, 0) repeats a lattice point (0, 0, 0)
}

// The cloud followed by a shuffled copy of itself: every point's result is the single copy's,
// bit for bit, and the counts are over all the points.
TEST(DuplicatePoints, ACloudGivenTwiceIsDenoisedAsTheSingleCopy) {
  PointList single = testing::NoisySphere(3000, 0.01, 11);
  single.emplace_back(0.0, 0.0, 0.0);  // an outlier inside the sphere, given twice too
  DenoiseOptions options = PresetOptions(Preset::kDefault);
  options.settings.num_threads = 2;
  options.minimizer.max_iterations = 15;
  const DenoiseResult alone = DenoisePointSet(single, options);
  ASSERT_GT(alone.num_removed, 0);

  std::vector<int> copy_of(single.size());
  for (size_t i = 0; i < single.size(); ++i) copy_of[i] = static_cast<int>(i);
  std::mt19937_64 random(5);
  std::shuffle(copy_of.begin(), copy_of.end(), random);
  PointList twice = single;
  std::vector<int> source(single.size());
  for (size_t i = 0; i < single.size(); ++i) source[i] = static_cast<int>(i);
  for (int i : copy_of) {
    twice.push_back(single[i]);
    source.push_back(i);
  }
  const DenoiseResult result = DenoisePointSet(twice, options);
  EXPECT_EQ(result.num_duplicates, static_cast<int>(single.size()));
  EXPECT_EQ(result.num_removed, 2 * alone.num_removed);
  EXPECT_EQ(result.num_outliers, 2 * alone.num_outliers);
  EXPECT_EQ(result.num_features, 2 * alone.num_features);
  for (size_t i = 0; i < twice.size(); ++i) {
    const int s = source[i];
    ASSERT_EQ(result.projected[i], alone.projected[s]) << i;
    ASSERT_EQ(result.normals[i], alone.normals[s]) << i;
    ASSERT_EQ(result.kept[i], alone.kept[s]) << i;
    ASSERT_EQ(result.indicators.outlier_score[i], alone.indicators.outlier_score[s]) << i;
    ASSERT_EQ(result.indicators.is_feature[i], alone.indicators.is_feature[s]) << i;
  }

  // Unmerged, each point's repeat dominates its pair weights and the data-derived lambda
  // collapses: the smoothing stops and most points read as features.
  DenoiseOptions unmerged = options;
  unmerged.merge_duplicates = false;
  const DenoiseResult raw = DenoisePointSet(twice, unmerged);
  EXPECT_EQ(raw.num_duplicates, 0);
  EXPECT_LT(raw.summary.lambda, 0.1 * result.summary.lambda);
}

}  // namespace
}  // namespace lpd::solvers
