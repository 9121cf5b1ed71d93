// Eq. (9): K against its definition, T against a dense solve, and T as a block minimizer.
#include "solvers/tangent_plane_smoothing.h"

#include <random>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "energy/energy.h"
#include "test_problems.h"

namespace lpd::solvers {
namespace {

class TangentPlaneSmoothingTest : public ::testing::Test {
 protected:
  void SetUp() override {
    energy::ProblemOptions options;
    options.k = 5;
    problem_ = energy::BuildProblem(testing::NoisySphere(80, 0.05, 31), options);
    parameters_ = testing::BalancedParameters();
    v_ = testing::RandomVariables(problem_, 6);
  }
  // K built densely from its definition: eta diag(alpha) + lambda sum beta m (e_i - s e_j)(.)^T
  Eigen::MatrixXd DenseK() const {
    const int n = problem_.num_points();
    Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i) k(i, i) = parameters_.eta * problem_.alpha[i];
    for (int p = 0; p < problem_.graph.num_pairs(); ++p) {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(n);
      e[problem_.graph.pairs[p][0]] += 1.0;
      e[problem_.graph.pairs[p][1]] -= v_.s[p];
      k += parameters_.lambda * problem_.beta[p] * v_.m[p] * e * e.transpose();
    }
    return k;
  }

  energy::Problem problem_;
  energy::EnergyParameters parameters_;
  energy::Variables v_;
};

TEST_F(TangentPlaneSmoothingTest, SystemMatrixMatchesDefinition) {
  TangentPlaneSmoother smoother(problem_);
  const Eigen::MatrixXd k = Eigen::MatrixXd(smoother.SystemMatrix(parameters_, v_));
  EXPECT_LT((k - DenseK()).norm(), 1e-12 * k.norm());
}

TEST_F(TangentPlaneSmoothingTest, SolveMatchesDenseFactorization) {
  const Eigen::MatrixXd k = DenseK();
  Eigen::MatrixXd w(problem_.num_points(), 4);
  for (int i = 0; i < problem_.num_points(); ++i) {
    w.row(i) = parameters_.eta * problem_.alpha[i] * v_.h.row(i);
  }
  const Eigen::MatrixXd expected = k.ldlt().solve(w);
  for (Preconditioner kind : {Preconditioner::kJacobi, Preconditioner::kMultilevel}) {
    energy::Variables v = v_;
    TangentPlaneSmoother smoother(problem_);
    LinearSolverOptions options;
    options.relative_tolerance = 1e-13;
    options.preconditioner = kind;
    const LinearSolveStats stats = smoother.Update(parameters_, options, 2, &v);
    EXPECT_LE(stats.relative_residual, 1e-13) << PreconditionerName(kind);
    EXPECT_LT((Eigen::MatrixXd(v.t) - expected).norm(), 1e-9 * expected.norm())
        << PreconditionerName(kind);
  }
}

TEST_F(TangentPlaneSmoothingTest, NoPerturbationLowersTheEnergy) {
  TangentPlaneSmoother smoother(problem_);
  LinearSolverOptions options;
  options.relative_tolerance = 1e-13;
  smoother.Update(parameters_, options, 1, &v_);
  const double best = energy::EvaluateEnergy(problem_, parameters_, v_).total();
  std::mt19937_64 rng(3);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    energy::Variables w = v_;
    const double size = trial % 2 ? 1e-4 : 0.1;
    w.t(trial % problem_.num_points(), trial % 4) += size * normal(rng);
    EXPECT_GE(energy::EvaluateEnergy(problem_, parameters_, w).total(), best * (1 - 1e-13));
  }
}

TEST_F(TangentPlaneSmoothingTest, InexactWarmStartedSolveNeverRaisesTheEnergy) {
  for (Preconditioner kind : {Preconditioner::kJacobi, Preconditioner::kMultilevel}) {
    energy::Variables v = v_;
    TangentPlaneSmoother smoother(problem_);
    LinearSolverOptions options;
    options.max_iterations = 1;
    options.preconditioner = kind;
    for (int round = 0; round < 10; ++round) {
      const double before = energy::EvaluateEnergy(problem_, parameters_, v).total();
      smoother.Update(parameters_, options, 1, &v);
      EXPECT_LE(energy::EvaluateEnergy(problem_, parameters_, v).total(), before * (1 + 1e-14))
          << PreconditionerName(kind);
    }
  }
}

}  // namespace
}  // namespace lpd::solvers
