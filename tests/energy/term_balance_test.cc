// The smoothness / stitching ratio against K's diagonal, and its growth with the density.
#include "energy/term_balance.h"

#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "energy/variables.h"
#include "solvers/tangent_plane_smoothing.h"
#include "test_problems.h"

namespace lpd::energy {
namespace {

TEST(TermBalance, IsTheMedianShareOfKsDiagonalAtUnitLineProcesses) {
  ProblemOptions options;
  options.k = 10;
  const Problem problem = BuildProblem(testing::NoisySphere(2001, 0.01, 3), options);
  EnergyParameters parameters;
  parameters.lambda = 1.7;
  // K of Eq. (9) at m = s = 1 (the initial variables): K_ii = eta alpha_i + smoothness.
  solvers::TangentPlaneSmoother smoother(problem);
  const auto k = smoother.SystemMatrix(parameters, InitialVariables(problem));
  std::vector<double> ratio;
  for (int i = 0; i < problem.num_points(); ++i) {
    const double stitching = parameters.eta * problem.alpha[i];
    ratio.push_back((k.coeff(i, i) - stitching) / stitching);
  }
  std::sort(ratio.begin(), ratio.end());
  EXPECT_NEAR(MedianSmoothnessToStitchingRatio(problem, parameters), ratio[1000],
              1e-12 * ratio[1000]);
}

TEST(TermBalance, GrowsInProportionToTheSamplingDensity) {
  // alpha_i shrinks like the squared point spacing, 1 / n on a fixed surface, while
  // sum_j beta_ij does not depend on the spacing: 4x the points, about 4x the ratio.
  const EnergyParameters parameters;
  const double sparse =
      MedianSmoothnessToStitchingRatio(BuildProblem(testing::NoisySphere(2000, 0.0, 5), ProblemOptions{}),
                                       parameters);
  const double dense =
      MedianSmoothnessToStitchingRatio(BuildProblem(testing::NoisySphere(8000, 0.0, 5), ProblemOptions{}),
                                       parameters);
  EXPECT_GT(dense / sparse, 3.5);
  EXPECT_LT(dense / sparse, 4.5);
}

}  // namespace
}  // namespace lpd::energy
