// The joint solve: its Ceres objective is Eq. (5) with optimal line processes, it
// keeps h_i on the sphere and lowers the energy, and on a noisy cube it is compared with the
// alternating driver of Alg. 1 from the same start.
#include "solvers/ceres_joint_solver.h"
#include "lpd/presets.h"
#include "solvers/sphere_projection.h"

#include <cmath>

#include <ceres/problem.h>
#include <gtest/gtest.h>

#include "energy/energy.h"
#include "energy/fitting_term.h"
#include "energy/smoothness_term.h"
#include "energy/stitching_term.h"
#include "experiments/shapes/noise.h"
#include "experiments/shapes/shape_catalog.h"
#include "solvers/alternating_minimizer.h"
#include "solvers/final_denoising.h"
#include "solvers/initial_state.h"
#include "test_problems.h"

namespace lpd::solvers {
namespace {

// Ceres' cost 1/2 sum rho(|f|^2) with every term's residuals added, at the state in `v`.
double CeresObjective(const energy::Problem& problem, const energy::EnergyParameters& w,
                      bool optimize_orientations, energy::Variables* v) {
  ceres::Problem joint;
  energy::FittingTerm(problem, w.mu_l).AddResiduals(v, &joint);
  energy::SmoothnessTerm(problem, w.lambda, w.mu_m).AddResiduals(v, optimize_orientations, &joint);
  energy::StitchingTerm(problem, w.eta).AddResiduals(v, &joint);
  double cost = 0.0;
  EXPECT_TRUE(joint.Evaluate(ceres::Problem::EvaluateOptions(), &cost, nullptr, nullptr, nullptr));
  return cost;
}

// Eq. (5) through the project's own terms, with L and M (and S if asked) at their closed
// forms (Eqs. 6-8), which is what eliminating them by Eq. (3) means.
double EnergyAtOptimalLineProcesses(const energy::Problem& problem,
                                    const energy::EnergyParameters& w, bool optimal_orientations,
                                    energy::Variables v) {
  energy::FittingTerm(problem, w.mu_l).UpdateLineProcesses(&v);
  const energy::SmoothnessTerm smoothness(problem, w.lambda, w.mu_m);
  if (optimal_orientations) smoothness.UpdateOrientations(&v);
  smoothness.UpdateLineProcesses(&v);
  return energy::EvaluateEnergy(problem, w, v).total();
}

TEST(CeresJointSolver, ObjectiveIsTheEnergyWithOptimalLineProcesses) {
  energy::ProblemOptions options;
  options.k = 6;
  const energy::Problem problem = energy::BuildProblem(testing::NoisySphere(200, 0.05, 3), options);
  // The paper's weights, with mu_l far below the residuals.
  const energy::EnergyParameters paper = PresetOptions(Preset::kPaper).settings.energy;
  for (const energy::EnergyParameters& w : {testing::BalancedParameters(), paper}) {
    for (uint64_t seed = 1; seed <= 5; ++seed) {
      energy::Variables v = testing::RandomVariables(problem, seed);
      for (bool blocks : {true, false}) {
        const double own = EnergyAtOptimalLineProcesses(problem, w, !blocks, v);
        const double ceres_cost = CeresObjective(problem, w, blocks, &v);
        EXPECT_NEAR(ceres_cost, own, 1e-10 * own)
            << "seed " << seed << (blocks ? " s as blocks" : " s at Eq. 8");
      }
    }
  }
}

// The energy `w` as it is, on two threads.
SolverSettings Settings(const energy::EnergyParameters& w) {
  SolverSettings settings;
  settings.energy = w;
  settings.mu_l_noise_sigmas = 0.0;
  settings.num_threads = 2;
  return settings;
}

TEST(CeresJointSolver, KeepsPlanesOnTheSphereAndLowersTheEnergy) {
  energy::ProblemOptions options;
  options.k = 8;
  const energy::Problem problem = energy::BuildProblem(testing::NoisySphere(400, 0.02, 4), options);
  const energy::EnergyParameters w = testing::BalancedParameters();
  for (bool blocks : {true, false}) {
    energy::Variables v = InitialState(problem, w, Initialization::kPlaneFit, 2);
    CeresJointSolver::Options joint;
    joint.optimize_orientations = blocks;
    joint.max_iterations = 10;
    const SolverSummary summary = CeresJointSolver::Minimize(problem, Settings(w), joint, &v);
    ASSERT_TRUE(summary.IsSolutionUsable()) << summary.message;
    EXPECT_LT(summary.final_energy.total(), summary.initial_energy.total());
    for (int i = 0; i < problem.num_points(); ++i) {
      ASSERT_NEAR(v.h.row(i).norm(), 1.0, 1e-12) << "h_" << i;
    }
    // The summary's energy is the state's energy with the line processes it left in v.
    EXPECT_NEAR(summary.final_energy.total(), energy::EvaluateEnergy(problem, w, v).total(),
                1e-12 * summary.final_energy.total());
    double previous_elapsed = 0.0;
    for (const IterationRecord& record : summary.iterations) {
      EXPECT_GE(record.elapsed_seconds, previous_elapsed);
      previous_elapsed = record.elapsed_seconds;
    }
  }
}

TEST(CeresJointSolver, RefusesPlanesOffTheSphere) {
  energy::ProblemOptions options;
  options.k = 6;
  const energy::Problem problem = energy::BuildProblem(testing::NoisySphere(100, 0.02, 5), options);
  energy::Variables v = energy::InitialVariables(problem);  // h = 0
  const SolverSummary summary =
      CeresJointSolver::Minimize(problem, {}, {}, &v);
  EXPECT_FALSE(summary.IsSolutionUsable());
  EXPECT_NE(summary.message.find("plane_fit"), std::string::npos) << summary.message;
}

double MeanDistance(const experiments::ProceduralShape& shape, const energy::PointList& points) {
  double sum = 0.0;
  for (const energy::Point3& p : points) sum += shape.DistanceToSurface(p);
  return sum / static_cast<double>(points.size());
}

// A noisy cube (2,000 points, sigma 0.5% of the diagonal, k = 10) with the paper's weights,
// minimized by both solvers from the same plane_fit state: the alternating driver with the
// paper's schedule (5 outer iterations), the joint solve to convergence. (One test, so that
// the joint solve runs once under ctest.)
TEST(CeresJointSolver, NoisyCubeAgainstTheAlternatingDriver) {
  const experiments::ProceduralShape cube = experiments::MakeShape({"cube", {}});
  experiments::NoiseOptions noise;
  noise.sigma = 0.005;
  noise.seed = 2;
  const energy::PointList input =
      experiments::ApplyNoise(cube.Sample(2000, 1).points, {}, noise).points;
  energy::ProblemOptions options;
  options.k = 10;
  const energy::Problem problem = energy::BuildProblem(input, options, 2);
  const energy::EnergyParameters w = PresetOptions(Preset::kPaper).settings.energy;
  const energy::Variables start = InitialState(problem, w, Initialization::kPlaneFit, 2);

  energy::Variables alternating = start;
  const DenoiseOptions paper = PresetOptions(Preset::kPaper);
  SolverSettings settings = paper.settings;
  settings.num_threads = 2;
  const SolverSummary alternating_summary =
      AlternatingMinimizer::Minimize(problem, settings, paper.minimizer, &alternating);
  energy::Variables joint = start;
  const SolverSummary joint_summary =
      CeresJointSolver::Minimize(problem, settings, CeresJointSolver::Options(), &joint);
  ASSERT_TRUE(alternating_summary.IsSolutionUsable()) << alternating_summary.message;
  ASSERT_EQ(joint_summary.termination, TerminationType::kConvergence) << joint_summary.message;

  // Both lower the same energy from the same start, and the stronger minimizer ends far
  // lower: the "within 1% or the alternating driver lower" does not hold for Eq. (5)
  // at the paper's weights (docs/method.md, "The joint solve minimizes the same default objective").
  const double alternating_energy = alternating_summary.final_energy.total();
  const double joint_energy = joint_summary.final_energy.total();
  EXPECT_LT(alternating_energy, joint_summary.initial_energy.total());
  EXPECT_LT(joint_energy, 1e-3 * alternating_energy);

  // The joint minimum is the collapsed state. With every h_i = t_i = one unit plane and s = 1,
  // smoothness and stitching vanish and each fitting residual costs at most alpha_i mu_l / 2
  // (Eq. 4 saturates at mu_l):
  double collapsed_bound = 0.0;
  for (int i = 0; i < problem.num_points(); ++i) {
    collapsed_bound += 0.5 * problem.alpha[i] * (problem.k() + 1) * w.mu_l;
  }
  EXPECT_LE(joint_energy, collapsed_bound * (1.0 + 1e-6));
  const Eigen::Vector4d t0 = joint.t.row(0).normalized();
  for (int i = 0; i < problem.num_points(); ++i) {
    ASSERT_GT(std::abs(joint.t.row(i).normalized().dot(t0)), 1.0 - 1e-6) << "t_" << i;
  }

  // So only the alternating schedule denoises the cube.
  energy::PointList projected, normals;
  const double input_distance = MeanDistance(cube, input);
  ProjectOntoBlendedSurfaces(problem, TangentPlaneSurfaces(alternating), 1, 0.0, false, 1,
                             &projected, &normals);
  EXPECT_LT(MeanDistance(cube, projected), 0.8 * input_distance);
  ProjectOntoBlendedSurfaces(problem, TangentPlaneSurfaces(joint), 1, 0.0, false, 1,
                             &projected, &normals);
  EXPECT_GT(MeanDistance(cube, projected), 10.0 * input_distance);
}

}  // namespace
}  // namespace lpd::solvers
