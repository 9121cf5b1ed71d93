// eta and lambda from the balances: the built problem has exactly the requested balances,
// and a cloud sampled 4x denser gets weights that keep them.
#include "energy/data_scaled_weights.h"

#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "energy/term_balance.h"
#include "test_problems.h"

namespace lpd::energy {
namespace {

double SortedMedianAlpha(const Problem& problem) {
  std::vector<double> alpha = problem.alpha;
  std::sort(alpha.begin(), alpha.end());
  return alpha[alpha.size() / 2];
}

Problem SphereProblem(int n) {
  ProblemOptions options;
  options.k = 15;
  return BuildProblem(testing::NoisySphere(n, 0.01, 2), options);
}

TEST(DataScaledWeights, TheProblemGetsTheRequestedBalances) {
  DataScaledWeights weights;
  weights.fit_balance = 0.7;
  weights.smoothing_balance = 3.0;
  for (int n : {2000, 8000}) {
    const Problem problem = SphereProblem(n);
    const EnergyParameters scaled = ScaleWeightsToData(problem, EnergyParameters(), weights);
    EXPECT_NEAR(scaled.eta / ((problem.k() + 1) * SortedMedianAlpha(problem)), 0.7, 1e-12) << n;
    EXPECT_NEAR(MedianSmoothnessToStitchingRatio(problem, scaled), 3.0, 1e-9) << n;
  }
}

TEST(DataScaledWeights, EtaFollowsTheDensityAndZeroBalancesKeepTheGivenWeights) {
  const DataScaledWeights weights;
  const EnergyParameters sparse = ScaleWeightsToData(SphereProblem(2000), EnergyParameters(),
                                                     weights);
  const EnergyParameters dense = ScaleWeightsToData(SphereProblem(8000), EnergyParameters(),
                                                    weights);
  // alpha scales with the squared spacing: 4x the points, a quarter of eta (to sampling noise).
  EXPECT_NEAR(dense.eta / sparse.eta, 0.25, 0.02);
  DataScaledWeights off;
  off.fit_balance = 0.0;
  off.smoothing_balance = 0.0;
  EnergyParameters given;
  given.eta = 123.0;
  given.lambda = 4.5;
  const EnergyParameters kept = ScaleWeightsToData(SphereProblem(2000), given, off);
  EXPECT_EQ(kept.eta, 123.0);
  EXPECT_EQ(kept.lambda, 4.5);
}

}  // namespace
}  // namespace lpd::energy
