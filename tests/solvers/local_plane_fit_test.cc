// The H update of Eq. (10) is the exact minimizer of Eq. (5) over each h_i on the sphere.
#include "solvers/local_plane_fit.h"

#include <random>

#include <gtest/gtest.h>

#include "energy/energy.h"
#include "test_problems.h"

namespace lpd::solvers {
namespace {

TEST(LocalPlaneFit, NoUnitPerturbationLowersTheEnergy) {
  energy::ProblemOptions options;
  options.k = 6;
  const energy::Problem problem = energy::BuildProblem(testing::NoisySphere(120, 0.05, 8), options);
  for (const double eta : {3.0, 5000.0}) {
    energy::EnergyParameters parameters = testing::BalancedParameters();
    parameters.eta = eta;
    energy::Variables v = testing::RandomVariables(problem, 1);
    UpdateLocalPlanes(problem, parameters, 2, &v);
    const double best = energy::EvaluateEnergy(problem, parameters, v).total();
    std::mt19937_64 rng(2);
    std::normal_distribution<double> normal(0.0, 1.0);
    for (int trial = 0; trial < 400; ++trial) {
      energy::Variables w = v;
      const int i = trial % problem.num_points();
      const double size = trial % 2 ? 1e-3 : 0.5;
      Eigen::RowVector4d h = w.h.row(i);
      for (int c = 0; c < 4; ++c) h[c] += size * normal(rng);
      w.h.row(i) = h.normalized();
      EXPECT_GE(energy::EvaluateEnergy(problem, parameters, w).total(), best * (1 - 1e-13));
    }
  }
}

TEST(LocalPlaneFit, FirstStepFitsTheDataPlane) {
  // From T = 0 and L = 1, h_i is the algebraic least-squares plane of N(i) u {i}: on exact
  // planar data it is the plane itself (z = 0 in the input frame).
  energy::ProblemOptions options;
  options.k = 8;
  const energy::Problem problem = energy::BuildProblem(testing::NoisyPlane(200, 0.0, 4), options);
  energy::Variables v = energy::InitialVariables(problem);
  UpdateLocalPlanes(problem, energy::EnergyParameters(), 1, &v);
  for (int i = 0; i < problem.num_points(); ++i) {
    const Eigen::Vector3d normal = v.h.row(i).head<3>().transpose().normalized();
    EXPECT_NEAR(std::abs(normal.z()), 1.0, 1e-9);
    EXPECT_NEAR(v.h.row(i).norm(), 1.0, 1e-12);
  }
}

}  // namespace
}  // namespace lpd::solvers
