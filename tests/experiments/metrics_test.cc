// Metrics on hand-made cases with answers computed by hand.
#include "experiments/evaluation/metrics.h"

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "experiments/shapes/shape_catalog.h"

namespace lpd::experiments {
namespace {

using energy::Point3;
using energy::PointList;

PointList Grid(int side) {
  PointList points;
  for (int x = 0; x < side; ++x) {
    for (int y = 0; y < side; ++y) {
      for (int z = 0; z < side; ++z) points.emplace_back(x, y, z);
    }
  }
  return points;
}

TEST(Metrics, APointSetAgainstItselfScoresZero) {
  const PointList grid = Grid(6);
  const Metrics metrics = ComputeMetrics(grid, PointSetGroundTruth(grid, "grid"), 2);
  EXPECT_EQ(metrics.mse, 0.0);
  EXPECT_EQ(metrics.mcd, 0.0);
  EXPECT_TRUE(std::isinf(metrics.snr_db));
  EXPECT_TRUE(std::isnan(metrics.mean_distance));  // a point set has no exact surface
}

TEST(Metrics, AShiftedSetHasTheHandComputedMseMcdAndSnr) {
  // On a unit grid, a shift by d (|d| < 1/2 per axis) keeps every nearest neighbour the
  // shifted twin, both ways and in both norms.
  const PointList grid = Grid(6);
  const Point3 d(0.1, -0.05, 0.02);
  PointList shifted = grid;
  for (Point3& p : shifted) p += d;
  const GroundTruth truth = PointSetGroundTruth(grid, "grid");
  const Metrics metrics = ComputeMetrics(shifted, truth, 2);
  EXPECT_NEAR(metrics.mse, 0.01 + 0.0025 + 0.0004, 1e-15);
  EXPECT_NEAR(metrics.mcd, 0.1 + 0.05 + 0.02, 1e-15);
  // Grid 0..5 per axis: centroid 2.5, mean squared offset per axis (2.5^2+1.5^2+0.5^2)/3.
  const double signal = 3.0 * (6.25 + 2.25 + 0.25) / 3.0;
  EXPECT_NEAR(metrics.snr_db, 10.0 * std::log10(signal / 0.0129), 1e-9);
  // Normalized columns divide by the diagonal (5 sqrt 3), squared for the MSE.
  const double diagonal = 5.0 * std::sqrt(3.0);
  for (const auto& [name, value] : metrics.Columns()) {
    if (name == "mse_normalized") {
      EXPECT_NEAR(value, 0.0129 / (diagonal * diagonal), 1e-15);
    } else if (name == "mcd_normalized") {
      EXPECT_NEAR(value, 0.17 / diagonal, 1e-15);
    }
  }
}

TEST(Metrics, TheTwoDirectionsAreAveraged) {
  // Output {0}; truth {0, (1,1,0)}: output->truth is 0, truth->output averages 0 and the
  // squared distance 2 (L1 length 2): MSE = (0 + 1) / 2, MCD = (0 + 1) / 2.
  const GroundTruth truth = PointSetGroundTruth({Point3::Zero(), Point3(1, 1, 0)}, "two");
  const Metrics metrics = ComputeMetrics({Point3::Zero()}, truth, 1);
  EXPECT_DOUBLE_EQ(metrics.mse, 0.5);
  EXPECT_DOUBLE_EQ(metrics.mcd, 0.5);
}

TEST(Metrics, McdUsesTheCityBlockNearestPoint) {
  // From the origin, (0.9, 0.9, 0) is L2-nearer (1.27) than (1.5, 0, 0) (1.5), but L1-farther
  // (1.8 > 1.5). Truth = output point set plus the origin's counterpart.
  const GroundTruth truth = PointSetGroundTruth({Point3(0.9, 0.9, 0), Point3(1.5, 0, 0)}, "t");
  const PointList output = {Point3::Zero(), Point3(0.9, 0.9, 0), Point3(1.5, 0, 0)};
  const Metrics metrics = ComputeMetrics(output, truth, 1);
  EXPECT_NEAR(metrics.mse, 0.5 * (1.62 / 3.0), 1e-12);
  EXPECT_NEAR(metrics.mcd, 0.5 * (1.5 / 3.0), 1e-12);
}

TEST(Metrics, ShapeGroundTruthGivesExactSurfaceDistances) {
  auto sphere = std::make_shared<const ProceduralShape>(MakeShape({"sphere", {}}));
  const GroundTruth truth = ShapeGroundTruth(sphere, 20000, 1);
  const Metrics metrics = ComputeMetrics({Point3(0, 0, 0.6), Point3(0.3, 0, 0)}, truth, 1);
  EXPECT_NEAR(metrics.mean_distance, 0.5 * (0.1 + 0.2), 1e-12);
  EXPECT_NEAR(metrics.max_distance, 0.2, 1e-12);
  EXPECT_NEAR(metrics.rms_distance, std::sqrt(0.5 * (0.01 + 0.04)), 1e-12);
}

TEST(Metrics, DetectionPrecisionAndRecall) {
  const DetectionScore score = ScoreDetection({1, 1, 0, 0, 1}, {1, 0, 1, 0, 1});
  EXPECT_EQ(score.true_positives, 2);
  EXPECT_EQ(score.false_positives, 1);
  EXPECT_EQ(score.false_negatives, 1);
  EXPECT_DOUBLE_EQ(score.precision(), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(score.recall(), 2.0 / 3.0);
  EXPECT_TRUE(std::isnan(ScoreDetection({0, 0}, {0, 0}).precision()));
  EXPECT_THROW(ScoreDetection({1}, {1, 0}), std::invalid_argument);
}

TEST(Metrics, TheDistanceThresholdBoundIsTheBestOfEveryThreshold) {
  // Farthest first: 8 (inlier), 7, 6, 5 (outliers), 1 (inlier), 0.5 (outlier), 0.2, 0.1.
  // Flagging the top 4 gives 3 of 4 outliers at precision 3/4: min 0.75; the top 6 give
  // precision 4/6 and recall 1; every other cut is lower.
  const std::vector<double> distances = {0.1, 7.0, 1.0, 5.0, 0.2, 6.0, 8.0, 0.5};
  const std::vector<uint8_t> labels = {0, 1, 0, 1, 0, 1, 0, 1};
  const ThresholdDetection best = BestDistanceThreshold(distances, labels);
  EXPECT_EQ(best.threshold, 5.0);
  EXPECT_EQ(best.score.true_positives, 3);
  EXPECT_EQ(best.score.false_positives, 1);
  EXPECT_EQ(best.score.false_negatives, 1);
  // Equal distances cannot be split: with the inlier at 1 moved to 5, the cut at 5 flags 3
  // outliers and 2 inliers (min 0.6), so the best cut is at 0.5: 4 outliers, 2 inliers.
  std::vector<double> tied = distances;
  tied[2] = 5.0;
  const ThresholdDetection tie = BestDistanceThreshold(tied, labels);
  EXPECT_EQ(tie.threshold, 0.5);
  EXPECT_EQ(tie.score.true_positives, 4);
  EXPECT_EQ(tie.score.false_positives, 2);
  EXPECT_THROW(BestDistanceThreshold({1.0}, {0}), std::invalid_argument);
  EXPECT_THROW(BestDistanceThreshold({1.0}, {1, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace lpd::experiments
