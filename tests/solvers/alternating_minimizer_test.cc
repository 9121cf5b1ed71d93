// Alg. 1: every block update is an exact minimizer, so the energy never increases from one
// block to the next (after the first H step puts H on the unit sphere).
#include "solvers/alternating_minimizer.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "test_problems.h"

namespace lpd::solvers {
namespace {

void ExpectMonotoneTrace(const SolverSummary& summary) {
  ASSERT_GT(summary.steps.size(), 2u);
  for (size_t s = 1; s < summary.steps.size(); ++s) {
    const double before = summary.steps[s - 1].energy.total();
    const double after = summary.steps[s].energy.total();
    EXPECT_LE(after, before + 1e-12 * std::abs(before))
        << "block " << summary.steps[s].block << " of iteration " << summary.steps[s].iteration
        << " raised the energy from " << before << " to " << after;
  }
}

energy::Problem PlaneProblem(int n, double sigma, uint64_t seed, int k) {
  energy::ProblemOptions problem_options;
  problem_options.k = k;
  return energy::BuildProblem(testing::NoisyPlane(n, sigma, seed), problem_options);
}

SolverSettings Fixed(const energy::EnergyParameters& parameters) {
  SolverSettings settings;
  settings.energy = parameters;
  settings.mu_l_noise_sigmas = 0.0;  // one energy throughout: mu_l stays the given one
  settings.num_threads = 2;
  return settings;
}

AlternatingMinimizer::Options TightOptions() {
  AlternatingMinimizer::Options options;
  options.max_iterations = 6;
  options.energy_tolerance = 0.0;
  options.progress_tolerance = 0.0;
  options.motion_tolerance = 0.0;
  options.linear_solver.relative_tolerance = 1e-12;
  return options;
}

// At most 50 iterations, stopped only by the tests given a positive tolerance.
AlternatingMinimizer::Options StoppingTests(double energy, double progress, double motion) {
  AlternatingMinimizer::Options options;
  options.max_iterations = 50;
  options.energy_tolerance = energy;
  options.progress_tolerance = progress;
  options.motion_tolerance = motion;
  return options;
}

TEST(AlternatingMinimizer, EnergyNeverIncreasesFromTheInitialization) {
  for (uint64_t seed : {1, 2, 3}) {
    energy::ProblemOptions problem_options;
    problem_options.k = 8;
    const energy::Problem problem =
        energy::BuildProblem(testing::NoisySphere(400, 0.03, seed), problem_options);
    for (const energy::EnergyParameters& parameters :
         {energy::EnergyParameters(), testing::BalancedParameters()}) {
      // The default's one (T, M, S) pass after each local step, and Alg. 1's two.
      for (int passes : {1, 2}) {
        energy::Variables v = energy::InitialVariables(problem);
        AlternatingMinimizer::Options options = TightOptions();
        options.inner_iterations = passes;
        const SolverSummary summary =
            AlternatingMinimizer::Minimize(problem, Fixed(parameters), options, &v);
        ASSERT_TRUE(summary.IsSolutionUsable()) << summary.message;
        EXPECT_EQ(summary.steps.size(), 6u * (2 + 3 * passes));
        ExpectMonotoneTrace(summary);
      }
    }
  }
}

TEST(AlternatingMinimizer, EnergyNeverIncreasesFromRandomStates) {
  const energy::Problem problem = PlaneProblem(300, 0.05, 9, 6);
  for (uint64_t seed : {4, 5}) {
    energy::Variables v = testing::RandomVariables(problem, seed);
    AlternatingMinimizer::Options options = TightOptions();
    options.inner_iterations = 3;
    ExpectMonotoneTrace(
        AlternatingMinimizer::Minimize(problem, Fixed(testing::BalancedParameters()), options, &v));
  }
}

TEST(AlternatingMinimizer, StopsOnTheEnergyWindowAndOnTheCallback) {
  const energy::Problem problem = PlaneProblem(200, 0.0, 2, 6);
  AlternatingMinimizer::Options options;
  options.max_iterations = 50;
  options.energy_tolerance = 0.5;  // generous: converges after window + 1 iterations at most
  energy::Variables v = energy::InitialVariables(problem);
  SolverSummary summary = AlternatingMinimizer::Minimize(problem, {}, options, &v);
  EXPECT_EQ(summary.termination, TerminationType::kConvergence);
  EXPECT_LT(summary.num_iterations, 50);

  v = energy::InitialVariables(problem);
  summary = AlternatingMinimizer::Minimize(
      problem, {}, options, &v, [](const IterationRecord& r) { return r.iteration < 2; });
  EXPECT_EQ(summary.termination, TerminationType::kUserAbort);
  EXPECT_EQ(summary.num_iterations, 2);
}

// The progress rule, checked on the recorded energies: the run stops at the first t (counted
// from 1) with E_{t-3} - E_t <= tol (E_1 - E_t), and only the progress test is on.
TEST(AlternatingMinimizer, StopsWhenTheLastIterationsGainLittleAgainstTheWholeRun) {
  const energy::Problem problem = PlaneProblem(300, 0.01, 3, 8);
  AlternatingMinimizer::Options options = StoppingTests(0.0, 0.05, 0.0);
  energy::Variables v = energy::InitialVariables(problem);
  const SolverSummary summary = AlternatingMinimizer::Minimize(
      problem, Fixed(testing::BalancedParameters()), options, &v);
  ASSERT_EQ(summary.termination, TerminationType::kConvergence) << summary.message;
  std::vector<double> e;
  for (const IterationRecord& record : summary.iterations) e.push_back(record.energy.total());
  const size_t w = options.energy_window;
  ASSERT_GT(e.size(), w + 2) << "stopped too early to tell the rule apart";
  auto met = [&](size_t t) {
    return e[t - w] - e[t] <= options.progress_tolerance * (e[0] - e[t]);
  };
  EXPECT_TRUE(met(e.size() - 1));
  for (size_t t = w; t + 1 < e.size(); ++t) EXPECT_FALSE(met(t)) << "iteration " << t + 1;
  EXPECT_NE(summary.message.find("fall since the first"), std::string::npos);

  options.progress_tolerance = -1.0;
  std::string error;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("progress_tolerance"), std::string::npos);
}

// The motion rule, checked on the recorded motions: with only the motion test on, the run
// stops at the first iteration whose last 3 motions are each at most tol x sigma, sigma the
// noise deviation behind the scale-aware mu_l (sqrt(mu_l) / c, c = mu_l_noise_sigmas).
TEST(AlternatingMinimizer, StopsWhenTheLastIterationsEachMoveTheOutputsLittle) {
  const energy::Problem problem = PlaneProblem(300, 0.01, 3, 8);
  AlternatingMinimizer::Options options = StoppingTests(0.0, 0.0, 0.02);
  SolverSettings settings;
  settings.energy = testing::BalancedParameters();
  energy::Variables v = energy::InitialVariables(problem);
  const SolverSummary summary = AlternatingMinimizer::Minimize(problem, settings, options, &v);
  ASSERT_EQ(summary.termination, TerminationType::kConvergence) << summary.message;
  const double sigma = std::sqrt(summary.mu_l) / settings.mu_l_noise_sigmas;
  std::vector<double> motion;
  for (const IterationRecord& record : summary.iterations) motion.push_back(record.point_motion);
  const size_t w = options.energy_window;
  ASSERT_GT(motion.size(), w + 2) << "stopped too early to tell the rule apart";
  auto met = [&](size_t t) {
    for (size_t j = t + 1 - w; j <= t; ++j) {
      if (!(motion[j] <= options.motion_tolerance * sigma * (1.0 + 1e-12))) return false;
    }
    return true;
  };
  EXPECT_TRUE(met(motion.size() - 1));
  for (size_t t = w; t + 1 < motion.size(); ++t) EXPECT_FALSE(met(t)) << "iteration " << t + 1;
  EXPECT_NE(summary.message.find("moved the output points"), std::string::npos);

  // Continued from where a first call stopped (before the window could be met), the run
  // stops at the same iteration with the same planes: the motions are carried over.
  energy::Variables continued = energy::InitialVariables(problem);
  MinimizerProgress progress;
  AlternatingMinimizer::Options first = options;
  first.max_iterations = 3;
  AlternatingMinimizer::Minimize(problem, settings, first, &continued, nullptr, &progress);
  const SolverSummary rest =
      AlternatingMinimizer::Minimize(problem, settings, options, &continued, nullptr, &progress);
  EXPECT_EQ(rest.num_iterations, summary.num_iterations);
  EXPECT_EQ(continued.t, v.t);

  options.motion_tolerance = NAN;
  std::string error;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("motion_tolerance"), std::string::npos);
}

TEST(AlternatingMinimizer, InvalidOptionsFailWithoutWork) {
  const energy::Problem problem = PlaneProblem(50, 0.01, 2, 4);
  SolverSettings settings;
  settings.energy.lambda = -1.0;
  energy::Variables v = energy::InitialVariables(problem);
  const SolverSummary summary = AlternatingMinimizer::Minimize(problem, settings, {}, &v);
  EXPECT_EQ(summary.termination, TerminationType::kFailure);
  EXPECT_NE(summary.message.find("lambda"), std::string::npos);
  EXPECT_EQ(summary.num_iterations, 0);
}

}  // namespace
}  // namespace lpd::solvers
