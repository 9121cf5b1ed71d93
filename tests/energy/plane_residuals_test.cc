// The Ceres pieces of Eq. (5): every residual's analytic Jacobian against Ceres' numeric
// differentiation (GradientChecker), and the Geman-McClure loss against its closed forms and
// finite differences.
#include "energy/plane_residuals.h"

#include <random>
#include <vector>

#include <ceres/gradient_checker.h>
#include <ceres/sphere_manifold.h>
#include <gtest/gtest.h>

#include "energy/geman_mcclure.h"
#include "energy/geman_mcclure_loss.h"

namespace lpd::energy {
namespace {

constexpr double kRelativePrecision = 1e-7;

// Runs the checker at `count` random points, filling blocks of `sizes` with N(0, 1) entries.
void ExpectJacobiansMatch(const ceres::CostFunction& cost, const std::vector<int>& sizes,
                          const std::vector<const ceres::Manifold*>* manifolds, int count,
                          uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  const ceres::GradientChecker checker(&cost, manifolds, ceres::NumericDiffOptions());
  for (int trial = 0; trial < count; ++trial) {
    std::vector<std::vector<double>> blocks;
    std::vector<const double*> pointers;
    for (int size : sizes) {
      blocks.emplace_back(size);
      for (double& x : blocks.back()) x = normal(rng);
    }
    for (const auto& block : blocks) pointers.push_back(block.data());
    ceres::GradientChecker::ProbeResults results;
    EXPECT_TRUE(checker.Probe(pointers.data(), kRelativePrecision, &results))
        << "trial " << trial << ": " << results.error_log;
  }
}

TEST(PlaneResiduals, DistanceJacobian) {
  const PlaneDistanceResidual cost(Point3(0.3, -1.2, 0.7));
  ExpectJacobiansMatch(cost, {4}, nullptr, 20, 1);
  // On the sphere the check runs in the tangent space, as the solver uses it.
  ceres::SphereManifold<4> sphere;
  const std::vector<const ceres::Manifold*> manifolds = {&sphere};
  ExpectJacobiansMatch(cost, {4}, &manifolds, 20, 2);
}

TEST(PlaneResiduals, DifferenceJacobian) {
  const PlaneDifferenceResidual cost;
  ExpectJacobiansMatch(cost, {4, 4, 1}, nullptr, 20, 3);
}

TEST(PlaneResiduals, AlignedDifferenceJacobian) {
  const AlignedPlaneDifferenceResidual cost;
  ExpectJacobiansMatch(cost, {4, 4}, nullptr, 50, 4);
}

TEST(PlaneResiduals, AlignedDifferenceIsTheDifferenceAtTheOptimalOrientation) {
  // f(t_i, t_j) equals t_i - s t_j with s minimizing |t_i - s t_j|^2, found by brute force.
  const Eigen::Vector4d ti(0.4, -1.0, 2.0, 0.3), tj(1.5, 0.2, -0.7, 1.1);
  const double* parameters[] = {ti.data(), tj.data()};
  Eigen::Vector4d f;
  ASSERT_TRUE(AlignedPlaneDifferenceResidual().Evaluate(parameters, f.data(), nullptr));
  double best = 1e300;
  for (double s = -3.0; s <= 3.0; s += 1e-5) best = std::min(best, (ti - s * tj).squaredNorm());
  EXPECT_NEAR(f.squaredNorm(), best, 1e-9);
  // With t_j = 0 every s is optimal and f = t_i.
  const Eigen::Vector4d zero = Eigen::Vector4d::Zero();
  const double* degenerate[] = {ti.data(), zero.data()};
  ASSERT_TRUE(AlignedPlaneDifferenceResidual().Evaluate(degenerate, f.data(), nullptr));
  EXPECT_EQ(f, ti);
}

TEST(PlaneResiduals, StitchingJacobian) {
  const PlaneStitchingResidual cost(3.7);
  ExpectJacobiansMatch(cost, {4, 4}, nullptr, 20, 5);
}

TEST(GemanMcClureLoss, ValueAndDerivatives) {
  for (double mu : {5e-9, 0.13, 2.0}) {
    const GemanMcClureLoss loss(mu);
    const GemanMcClure penalty(mu);
    for (double s : {0.0, 0.1 * mu, mu, 7.0 * mu, 1e3 * mu}) {
      double rho[3];
      loss.Evaluate(s, rho);
      // rho(s) = s / (1 + s / mu) (Eq. 4); rho'(s) is the optimal line process (Eq. 6).
      EXPECT_NEAR(rho[0], s / (1.0 + s / mu), 1e-14 * mu);
      EXPECT_NEAR(rho[1], penalty.OptimalLineProcess(s), 1e-14);
      if (s == 0.0) continue;
      // Central differences of rho and rho'.
      const double h = 1e-4 * s;
      double below[3], above[3];
      loss.Evaluate(s - h, below);
      loss.Evaluate(s + h, above);
      EXPECT_NEAR(rho[1], (above[0] - below[0]) / (2.0 * h), 1e-6 * rho[1])
          << "mu " << mu << " s " << s;
      EXPECT_NEAR(rho[2], (above[1] - below[1]) / (2.0 * h), 1e-6 * std::abs(rho[2]))
          << "mu " << mu << " s " << s;
    }
  }
}

}  // namespace
}  // namespace lpd::energy
