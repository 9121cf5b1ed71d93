// Normalization, alpha_i and beta_ij by their formulas, and input validation.
#include "energy/problem.h"

#include <cmath>

#include <gtest/gtest.h>

#include "test_problems.h"

namespace lpd::energy {
namespace {

TEST(Problem, NormalizedFrameHasUnitDiagonalAndZeroCentroid) {
  PointList points = testing::NoisySphere(400, 0.02, 11);
  for (Point3& p : points) p = 37.0 * p + Point3(100, -5, 2);
  ProblemOptions options;
  options.k = 8;
  const Problem problem = BuildProblem(points, options);
  EXPECT_NEAR(BoundingBoxDiagonal(problem.points), 1.0, 1e-12);
  Point3 centroid = Point3::Zero();
  for (const Point3& p : problem.points) centroid += p;
  EXPECT_LT((centroid / 400.0).norm(), 1e-12);
  for (int i = 0; i < 400; ++i) {
    EXPECT_LT((problem.frame.ToInput(problem.points[i]) - points[i]).norm(), 1e-10);
  }
}

// Coordinates whose squares over- or underflow a double still normalize exactly.
TEST(Problem, NormalizesExtremeCoordinateScales) {
  for (const double scale : {1e200, 1e-200, 1e307}) {
    PointList points = testing::NoisySphere(300, 0.02, 3);
    const double reference = BoundingBoxDiagonal(points);
    for (Point3& p : points) p *= scale;
    EXPECT_NEAR(BoundingBoxDiagonal(points) / scale, reference, 1e-12 * reference) << scale;
    ProblemOptions options;
    options.k = 8;
    const Problem problem = BuildProblem(points, options);
    EXPECT_NEAR(BoundingBoxDiagonal(problem.points), 1.0, 1e-12) << scale;
    EXPECT_LT((problem.frame.ToInput(problem.points[7]) - points[7]).stableNorm(), 1e-12 * scale);
  }
  const PointList beyond = {{-1e308, 0, 0}, {1e308, 0, 0}, {0, 1, 0}};
  try {
    ComputeNormalizingFrame(beyond);
    ADD_FAILURE() << "an extent beyond the largest double was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("overflows"), std::string::npos) << error.what();
  }
}

TEST(Problem, WeightsFollowTheirDefinitions) {
  const PointList points = testing::NoisySphere(300, 0.05, 2);
  ProblemOptions options;
  options.k = 7;
  const Problem problem = BuildProblem(points, options);
  const auto& p = problem.points;
  double mean_alpha = 0.0;
  for (int i = 0; i < problem.num_points(); ++i) {
    double sum = 0.0;
    for (int a = 0; a < 7; ++a) sum += (p[i] - p[problem.graph.NeighborsOf(i)[a]]).squaredNorm();
    mean_alpha += sum / 7.0 / problem.num_points();
  }
  // The documented duplicate guard: squared distances are floored at ratio * mean alpha.
  const double floor = options.min_squared_distance_ratio * mean_alpha;
  for (int i = 0; i < problem.num_points(); ++i) {
    double sum = 0.0;
    for (int a = 0; a < 7; ++a) sum += (p[i] - p[problem.graph.NeighborsOf(i)[a]]).squaredNorm();
    EXPECT_NEAR(problem.alpha[i], sum / 7.0, 1e-15);
  }
  for (int q = 0; q < problem.graph.num_pairs(); ++q) {
    const int i = problem.graph.pairs[q][0];
    const int j = problem.graph.pairs[q][1];
    const double expected = (problem.alpha[i] / 7.0 + problem.alpha[j] / 7.0) /
                            std::max((p[i] - p[j]).squaredNorm(), floor);
    EXPECT_NEAR(problem.beta[q], expected, 1e-12 * expected);
  }
}

TEST(Problem, DuplicatePointsGiveFiniteWeights) {
  PointList points = testing::NoisyPlane(100, 0.01, 4);
  for (int i = 0; i < 30; ++i) points.push_back(points[i]);
  for (int copy = 0; copy < 10; ++copy) points.push_back(points[50]);
  ProblemOptions options;
  options.k = 5;
  const Problem problem = BuildProblem(points, options);
  for (double a : problem.alpha) {
    EXPECT_TRUE(std::isfinite(a));
    EXPECT_GT(a, 0.0);
  }
  for (double b : problem.beta) {
    EXPECT_TRUE(std::isfinite(b));
    EXPECT_GT(b, 0.0);
  }
}

TEST(Problem, RejectsInvalidInput) {
  ProblemOptions options;
  options.k = 4;
  PointList points = testing::NoisyPlane(20, 0.01, 1);
  PointList with_nan = points;
  with_nan[3].y() = std::nan("");
  EXPECT_THROW(BuildProblem(with_nan, options), std::invalid_argument);
  PointList with_inf = points;
  with_inf[5].z() = INFINITY;
  EXPECT_THROW(BuildProblem(with_inf, options), std::invalid_argument);
  EXPECT_THROW(BuildProblem(PointList(points.begin(), points.begin() + 4), options),
               std::invalid_argument);
  EXPECT_THROW(BuildProblem(PointList(20, Point3(1, 2, 3)), options), std::invalid_argument);
  options.k = 0;
  EXPECT_THROW(BuildProblem(points, options), std::invalid_argument);
}

}  // namespace
}  // namespace lpd::energy
