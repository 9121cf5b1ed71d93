// The three terms of Eq. (5) against a direct transcription, and the closed-form L, M, S
// updates as exact block minimizers (no perturbation lowers the energy).
#include <random>

#include <gtest/gtest.h>

#include "energy/energy.h"
#include "energy/fitting_term.h"
#include "energy/smoothness_term.h"
#include "test_problems.h"

namespace lpd::energy {
namespace {

double Psi(double mu, double z) { return mu * (std::sqrt(z) - 1.0) * (std::sqrt(z) - 1.0); }

// Eq. (5) written out term by term, independently of the cost objects.
EnergyBreakdown DirectEnergy(const Problem& problem, const EnergyParameters& w,
                             const Variables& v) {
  EnergyBreakdown e;
  const int k = problem.k();
  for (int i = 0; i < problem.num_points(); ++i) {
    for (int a = 0; a <= k; ++a) {
      const int j = a == 0 ? i : problem.graph.neighbors[i * k + a - 1];
      Eigen::Vector4d q;
      q << problem.points[j], 1.0;
      const double hq = v.h.row(i).dot(q.transpose());
      e.fitting += 0.5 * problem.alpha[i] * (hq * hq * v.l(i, a) + Psi(w.mu_l, v.l(i, a)));
    }
    e.stitching += 0.5 * w.eta * problem.alpha[i] * (v.h.row(i) - v.t.row(i)).squaredNorm();
  }
  for (int p = 0; p < problem.graph.num_pairs(); ++p) {
    const int i = problem.graph.pairs[p][0];
    const int j = problem.graph.pairs[p][1];
    const double d2 = (v.t.row(i) - v.s[p] * v.t.row(j)).squaredNorm();
    e.smoothness += 0.5 * w.lambda * problem.beta[p] * (d2 * v.m[p] + Psi(w.mu_m, v.m[p]));
  }
  return e;
}

class EnergyTermsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ProblemOptions options;
    options.k = 6;
    problem_ = BuildProblem(testing::NoisySphere(150, 0.05, 21), options);
    parameters_ = testing::BalancedParameters();
    v_ = testing::RandomVariables(problem_, 5);
  }
  double Total(const Variables& v) const { return EvaluateEnergy(problem_, parameters_, v).total(); }

  Problem problem_;
  EnergyParameters parameters_;
  Variables v_;
};

TEST_F(EnergyTermsTest, TermsMatchDirectTranscription) {
  const EnergyBreakdown e = EvaluateEnergy(problem_, parameters_, v_, 2);
  const EnergyBreakdown d = DirectEnergy(problem_, parameters_, v_);
  EXPECT_NEAR(e.fitting, d.fitting, 1e-12 * d.fitting);
  EXPECT_NEAR(e.smoothness, d.smoothness, 1e-12 * d.smoothness);
  EXPECT_NEAR(e.stitching, d.stitching, 1e-12 * d.stitching);
}

TEST_F(EnergyTermsTest, FittingLineProcessesAreBlockMinimizers) {
  FittingTerm(problem_, parameters_.mu_l).UpdateLineProcesses(&v_);
  const double best = Total(v_);
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> entry(0, static_cast<int>(v_.l.size()) - 1);
  for (int trial = 0; trial < 300; ++trial) {
    Variables w = v_;
    double& z = w.l.data()[entry(rng)];
    for (double delta : {-1e-3, 1e-3, -0.1, 0.1}) {
      const double saved = z;
      z = std::clamp(saved + delta, 0.0, 1.0);
      EXPECT_GE(Total(w), best - 1e-13 * best);
      z = saved;
    }
  }
}

TEST_F(EnergyTermsTest, SmoothnessLineProcessesAndOrientationsAreBlockMinimizers) {
  const SmoothnessTerm smoothness(problem_, parameters_.lambda, parameters_.mu_m);
  smoothness.UpdateOrientations(&v_);
  double best = Total(v_);
  std::mt19937_64 rng(4);
  std::uniform_int_distribution<int> pair(0, problem_.graph.num_pairs() - 1);
  for (int trial = 0; trial < 300; ++trial) {
    Variables w = v_;
    const int p = pair(rng);
    for (double delta : {-1e-4, 1e-4, -0.3, 0.3}) {
      w.s[p] = v_.s[p] + delta;
      EXPECT_GE(Total(w), best - 1e-13 * best) << "s perturbation lowered the energy";
    }
  }
  smoothness.UpdateLineProcesses(&v_);
  best = Total(v_);
  for (int trial = 0; trial < 300; ++trial) {
    Variables w = v_;
    const int p = pair(rng);
    for (double delta : {-1e-3, 1e-3, -0.2, 0.2}) {
      w.m[p] = std::clamp(v_.m[p] + delta, 0.0, 1.0);
      EXPECT_GE(Total(w), best - 1e-13 * best) << "m perturbation lowered the energy";
    }
  }
}

}  // namespace
}  // namespace lpd::energy
