// The joint-solve baseline: its Ceres objective is Eq. (5) with optimal line processes, it
// keeps h_i on the sphere and lowers the energy, and on a noisy cube it is compared with the
// alternating driver of Alg. 1 from the same start.
#include "solvers/ceres_joint_solver.h"

#include <cmath>

#include <ceres/problem.h>
#include <gtest/gtest.h>

#include "energy/energy.h"
#include "energy/fitting_term.h"
#include "energy/smoothness_term.h"
#include "energy/stitching_term.h"
#include "experiments/noise.h"
#include "experiments/shape_catalog.h"
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
  energy::EnergyParameters paper;  // the paper's weights, with mu_l far below the residuals
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
    joint.num_threads = 2;
    const SolverSummary summary = CeresJointSolver::Minimize(problem, w, joint, &v);
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
      CeresJointSolver::Minimize(problem, energy::EnergyParameters(), {}, &v);
  EXPECT_FALSE(summary.IsSolutionUsable());
  EXPECT_NE(summary.message.find("plane_fit"), std::string::npos) << summary.message;
}

// A noisy cube (2,000 points, sigma 0.5% of the diagonal, k = 10) with the paper's weights,
// minimized by both solvers from the same plane_fit state: the alternating driver with the
// paper's schedule (5 outer iterations), the joint solve to convergence.
class NoisyCubeComparison : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    cube_ = new experiments::ProceduralShape(experiments::MakeShape({"cube", {}}));
    experiments::NoiseOptions noise;
    noise.sigma = 0.005;
    noise.seed = 2;
    input_ = experiments::ApplyNoise(cube_->Sample(2000, 1).points, {}, noise).points;
    energy::ProblemOptions options;
    options.k = 10;
    problem_ = new energy::Problem(energy::BuildProblem(input_, options, 2));
    const energy::Variables start = InitialState(*problem_, w_, Initialization::kPlaneFit, 2);

    alternating_ = start;
    AlternatingMinimizer::Options schedule;
    schedule.num_threads = 2;
    alternating_summary_ = AlternatingMinimizer::Minimize(*problem_, schedule, &alternating_);

    joint_ = start;
    CeresJointSolver::Options joint;
    joint.num_threads = 2;
    joint_summary_ = CeresJointSolver::Minimize(*problem_, w_, joint, &joint_);
  }
  static void TearDownTestSuite() {
    delete cube_;
    delete problem_;
  }

  static double MeanDistance(const energy::PointList& points) {
    double sum = 0.0;
    for (const energy::Point3& p : points) sum += cube_->DistanceToSurface(p);
    return sum / static_cast<double>(points.size());
  }
  static double MeanDistance(const energy::Variables& v) {
    energy::PointList projected, normals;
    ProjectOntoTangentPlanes(*problem_, v, &projected, &normals);
    return MeanDistance(projected);
  }

  static inline const energy::EnergyParameters w_{};
  static inline experiments::ProceduralShape* cube_ = nullptr;
  static inline energy::PointList input_;
  static inline energy::Problem* problem_ = nullptr;
  static inline energy::Variables alternating_, joint_;
  static inline SolverSummary alternating_summary_, joint_summary_;
};

TEST_F(NoisyCubeComparison, BothLowerTheEnergyAndTheJointSolveEndsLower) {
  ASSERT_TRUE(alternating_summary_.IsSolutionUsable()) << alternating_summary_.message;
  ASSERT_EQ(joint_summary_.termination, TerminationType::kConvergence) << joint_summary_.message;
  const double start = joint_summary_.initial_energy.total();
  EXPECT_LT(alternating_summary_.final_energy.total(), start);
  // The same energy, so the stronger minimizer ends lower: the issue's "within 1% or the
  // alternating driver lower" does not hold for Eq. (5) at the paper's weights (see README).
  EXPECT_LT(joint_summary_.final_energy.total(), 1e-3 * alternating_summary_.final_energy.total());
}

TEST_F(NoisyCubeComparison, JointMinimumIsTheCollapsedState) {
  // With every h_i = t_i = one unit plane and s = 1, smoothness and stitching vanish and each
  // fitting residual costs at most alpha_i mu_l / 2 (Eq. 4 saturates at mu_l):
  double collapsed_bound = 0.0;
  for (int i = 0; i < problem_->num_points(); ++i) {
    collapsed_bound += 0.5 * problem_->alpha[i] * (problem_->k() + 1) * w_.mu_l;
  }
  EXPECT_LE(joint_summary_.final_energy.total(), collapsed_bound * (1.0 + 1e-6));
  EXPECT_LT(collapsed_bound, 1e-3 * alternating_summary_.final_energy.total());
  // ...and the joint solve found that state: every t_i is parallel to t_0.
  const Eigen::Vector4d t0 = joint_.t.row(0).normalized();
  for (int i = 0; i < problem_->num_points(); ++i) {
    const Eigen::Vector4d ti = joint_.t.row(i).normalized();
    ASSERT_GT(std::abs(ti.dot(t0)), 1.0 - 1e-6) << "t_" << i;
  }
}

TEST_F(NoisyCubeComparison, OnlyTheAlternatingScheduleDenoises) {
  const double input = MeanDistance(input_);
  EXPECT_LT(MeanDistance(alternating_), 0.8 * input);
  EXPECT_GT(MeanDistance(joint_), 10.0 * input);
}

}  // namespace
}  // namespace lpd::solvers
