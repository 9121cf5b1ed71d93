// RmsProjectedPointChange against hand-computed projections.
#include "solvers/residual_statistics.h"

#include <cmath>

#include <gtest/gtest.h>

namespace lpd::solvers {
namespace {

TEST(RmsProjectedPointChange, MatchesTheHandComputedMotionOfTheProjections) {
  energy::Problem problem;
  problem.points = {energy::Point3(0.1, 0.2, 0.05), energy::Point3(-0.3, 0.1, -0.02),
                    energy::Point3(0.0, 0.0, 0.3)};
  energy::PlaneField before(3, 4), after(3, 4);
  // Point 0: from the plane z = 0 to z = 0.1 (t = (0, 0, 2, -0.2): scale does not matter):
  // its projection moves from (0.1, 0.2, 0) to (0.1, 0.2, 0.1), by 0.1.
  before.row(0) << 0, 0, 1, 0;
  after.row(0) << 0, 0, 2, -0.2;
  // Point 1: from z = 0 to x = 0: (-0.3, 0.1, 0) -> (0, 0.1, -0.02), by sqrt(0.09 + 0.0004).
  before.row(1) << 0, 0, 1, 0;
  after.row(1) << 1, 0, 0, 0;
  // Point 2: no plane before (zero normal): counts as unmoved.
  before.row(2) << 0, 0, 0, 0;
  after.row(2) << 0, 0, 1, 0;
  const double expected = std::sqrt((0.01 + 0.09 + 0.0004 + 0.0) / 3.0);
  for (int threads : {1, 2}) {
    EXPECT_NEAR(RmsProjectedPointChange(problem, before, after, threads), expected, 1e-15);
  }
  EXPECT_EQ(RmsProjectedPointChange(problem, after, after, 1), 0.0);
}

}  // namespace
}  // namespace lpd::solvers
