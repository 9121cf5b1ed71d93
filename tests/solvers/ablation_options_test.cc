// The ablation options of Alg. 1: s_ij held at 1 (Fig. 4), the initializations, the
// scale-aware mu_l and graduated non-convexity, each checked against what it must do.
#include <cmath>

#include <gtest/gtest.h>

#include "experiments/shapes/noise.h"
#include "experiments/shapes/shape_catalog.h"
#include "solvers/denoise_point_set.h"
#include "lpd/presets.h"
#include "solvers/residual_statistics.h"
#include "test_problems.h"

namespace lpd::solvers {
namespace {

// The paper's setting, which these ablations vary one option of.
DenoiseOptions BaseOptions() {
  DenoiseOptions options = PresetOptions(Preset::kPaper);
  options.settings.num_threads = 2;
  return options;
}

// Pairs of M whose planes' normals point in opposite directions once s_ij is applied: the
// orientation flips of Fig. 4 (with s held at 1, any pair with n_i . n_j < 0).
int CountFlips(const DenoiseState& state) {
  const energy::Variables& v = state.variables;
  const energy::NeighborGraph& graph = state.problem.graph;
  int flips = 0;
  for (int p = 0; p < graph.num_pairs(); ++p) {
    const Eigen::Vector3d ni = v.t.row(graph.pairs[p][0]).head<3>().normalized();
    const Eigen::Vector3d nj = v.t.row(graph.pairs[p][1]).head<3>().normalized();
    flips += v.s[p] * ni.dot(nj) < 0.0;
  }
  return flips;
}

TEST(AblationOptions, OrientationsHeldAtOneLeaveFlipsThatOptimizedOrientationsRemove) {
  // A sphere has one consistent orientation and no sharp feature. The first local fit gives
  // every PCA plane an arbitrary sign; with s = 1 the smoothness term cannot reconcile them,
  // so about half of the neighbours stay flipped and the line processes cut them as if they
  // were features (the artifacts of Fig. 4, left). With s optimized there are none.
  for (uint64_t seed : {1, 2}) {
    const energy::PointList points = testing::NoisySphere(4000, 0.01, seed);
    for (bool optimize : {false, true}) {
      DenoiseOptions options = BaseOptions();
      options.minimizer.optimize_orientations = optimize;
      DenoiseState state = StartDenoising(points, options);
      SolverSummary summary = MinimizeFromState(options, &state);
      const int num_pairs = state.problem.graph.num_pairs();
      const int flips = CountFlips(state);
      const DenoiseResult result = FinishDenoising(state, options, std::move(summary));
      if (optimize) {
        EXPECT_EQ(flips, 0) << "seed " << seed;
        EXPECT_LE(result.num_features, 4) << "seed " << seed;
      } else {
        EXPECT_TRUE((state.variables.s.array() == 1.0).all());
        EXPECT_GT(flips, num_pairs / 4) << "seed " << seed;
        EXPECT_GT(result.num_features, 100) << "seed " << seed;
      }
    }
  }
}

TEST(AblationOptions, RandomInitializationIsSeededAndUnitLength) {
  energy::ProblemOptions problem_options;
  const energy::Problem problem =
      energy::BuildProblem(testing::NoisySphere(500, 0.01, 3), problem_options);
  const energy::EnergyParameters parameters;
  const energy::Variables a = InitialState(problem, parameters, Initialization::kRandom, 2, 7);
  const energy::Variables b = InitialState(problem, parameters, Initialization::kRandom, 2, 7);
  const energy::Variables c = InitialState(problem, parameters, Initialization::kRandom, 2, 8);
  EXPECT_TRUE(a.h == b.h);
  EXPECT_FALSE(a.h == c.h);
  EXPECT_TRUE(a.t == a.h);
  Eigen::Vector4d mean = Eigen::Vector4d::Zero();
  for (int i = 0; i < problem.num_points(); ++i) {
    EXPECT_NEAR(a.h.row(i).norm(), 1.0, 1e-12);
    mean += a.h.row(i).transpose() / problem.num_points();
  }
  // Uniform on the sphere: each coordinate has mean 0 and standard deviation 1/2, so the
  // mean of 500 is within 4 standard errors (4 x 0.5 / sqrt(500) = 0.09) of 0.
  EXPECT_LT(mean.cwiseAbs().maxCoeff(), 0.09);
}

TEST(AblationOptions, InputNormalsGivePlanesThroughThePointsWithThoseNormals) {
  const energy::PointList points = testing::NoisySphere(500, 0.0, 4);
  energy::PointList normals;
  for (const energy::Point3& p : points) normals.push_back(-2.0 * p);  // any length, inward
  DenoiseOptions options = BaseOptions();
  options.initialization = Initialization::kInputNormals;
  const DenoiseState state = StartDenoising(points, options, &normals);
  const energy::Problem& problem = state.problem;
  for (int r = 0; r < problem.num_points(); ++r) {
    const Eigen::Vector4d h = state.variables.h.row(r).transpose();
    const energy::Point3& p = problem.points[r];
    EXPECT_NEAR(h.norm(), 1.0, 1e-12);
    EXPECT_NEAR(h.head<3>().dot(p) + h[3], 0.0, 1e-12);  // the plane passes through p
    const Eigen::Vector3d given = -points[state.order[r]].normalized();
    EXPECT_NEAR(h.head<3>().normalized().dot(given), 1.0, 1e-12);
  }
  options.initialization = Initialization::kInputNormals;
  EXPECT_THROW(StartDenoising(points, options), std::invalid_argument);
}

TEST(AblationOptions, RobustResidualScaleEstimatesTheNoise) {
  // Points on a plane with Gaussian noise sigma along its normal: the residuals of a PCA
  // plane fitted to k + 1 points have variance sigma^2 (1 - 3 / (k + 1)) (three fitted
  // parameters), so the normalized median absolute residual must be near that. (With noise
  // comparable to the sample spacing, 0.013 here, the k-NN search prefers neighbours near
  // p_i's own offset and the estimate drops: 0.9x at sigma = 0.01.)
  for (double sigma : {0.001, 0.003}) {
    energy::ProblemOptions problem_options;
    const energy::Problem problem =
        energy::BuildProblem(testing::NoisyPlane(6000, sigma, 5), problem_options);
    const energy::Variables v =
        InitialState(problem, energy::EnergyParameters(), Initialization::kPlaneFit, 2);
    const double expected =
        sigma / problem.frame.scale * std::sqrt(1.0 - 3.0 / (problem_options.k + 1));
    EXPECT_NEAR(RobustFittingResidualScale(problem, v), expected, 0.1 * expected)
        << "sigma " << sigma;
  }
}

TEST(AblationOptions, ScaleAwareMuLIsSetFromTheFirstLocalFit) {
  const energy::PointList points = testing::NoisyPlane(3000, 0.01, 6);
  DenoiseOptions options = BaseOptions();
  options.settings.mu_l_noise_sigmas = 3.0;
  options.minimizer.max_iterations = 1;
  DenoiseState state = StartDenoising(points, options);
  const SolverSummary summary = MinimizeFromState(options, &state);
  // After one iteration H is the first local fit (from the zero start, l = 1 and t = 0).
  DenoiseState first_fit = StartDenoising(points, options);
  options.initialization = Initialization::kPlaneFit;
  const double scale = RobustFittingResidualScale(
      first_fit.problem,
      InitialState(first_fit.problem, options.settings.energy, Initialization::kPlaneFit, 2));
  EXPECT_DOUBLE_EQ(summary.mu_l, 9.0 * scale * scale);
  EXPECT_DOUBLE_EQ(state.progress.mu_l, summary.mu_l);
  EXPECT_DOUBLE_EQ(summary.iterations[0].mu_l, summary.mu_l);
}

TEST(AblationOptions, ContinuationFollowsItsGeometricSchedule) {
  const energy::PointList points = testing::NoisySphere(2000, 0.01, 7);
  DenoiseOptions options = BaseOptions();
  options.minimizer.gnc.target = GncTarget::kBoth;
  options.minimizer.gnc.factor = 2.0;
  options.minimizer.gnc.stage_iterations = 2;
  options.minimizer.max_iterations = 40;
  options.minimizer.energy_tolerance = 0.0;
  options.minimizer.progress_tolerance = 0.0;
  options.minimizer.motion_tolerance = 0.0;
  DenoiseState state = StartDenoising(points, options);
  const SolverSummary summary = MinimizeFromState(options, &state);
  const energy::EnergyParameters& target = options.settings.energy;
  // The convex start 3 max r^2, from the residuals after the first H and T updates; a
  // fresh run stopped right after them measures those residuals.
  const double mu_m0 = summary.iterations[0].mu_m;
  const double mu_l0 = summary.iterations[0].mu_l;
  EXPECT_GT(mu_l0, target.mu_l);
  EXPECT_GT(mu_m0, target.mu_m);
  for (const IterationRecord& record : summary.iterations) {
    const double shrink = std::pow(2.0, (record.iteration - 1) / 2);  // 2 iterations per stage
    EXPECT_DOUBLE_EQ(record.mu_l, std::max(target.mu_l, mu_l0 / shrink));
    EXPECT_DOUBLE_EQ(record.mu_m, std::max(target.mu_m, mu_m0 / shrink));
  }
  EXPECT_EQ(summary.iterations.back().mu_m, target.mu_m);
}

TEST(AblationOptions, ConvexStartCoversEveryResidual) {
  energy::ProblemOptions problem_options;
  const energy::Problem problem =
      energy::BuildProblem(testing::NoisySphere(800, 0.02, 8), problem_options);
  const energy::Variables v =
      InitialState(problem, energy::EnergyParameters(), Initialization::kPlaneFit, 2);
  // Brute force over every residual, independently of the parallel reduction.
  double largest = 0.0;
  for (int i = 0; i < problem.num_points(); ++i) {
    for (int a = 0; a <= problem.k(); ++a) {
      const energy::Point3& q = problem.points[problem.graph.FittingPoint(i, a)];
      const double r = v.h.row(i).head<3>().dot(q) + v.h(i, 3);
      largest = std::max(largest, r * r);
    }
  }
  EXPECT_DOUBLE_EQ(MaxSquaredFittingResidual(problem, v, 2), largest);
  GncOptions gnc;
  ContinuedSelectivity mu;
  mu.Start(gnc, 5e-9, largest);
  // rho_mu is convex where x^2 < mu / 3: at the start that holds for every residual.
  EXPECT_GE(mu.current / 3.0, largest);
}

// GNC must not end at a higher energy of Eq. (5) than the same run without it. Measured on
// cubes at 1% noise, seeds 1-4, both runs to convergence: continuing mu_m (or both) ends
// about 20% lower. Continuing mu_l alone ends within 1e-5 (relative) of the run without
// it, sometimes above: at eta = 5000 the stitching term pins h_i to t_i and mu_l hardly
// changes the minimizer (docs/method.md), so both runs stop at nearly the same state and only
// the last digits of where the 1% stopping test fires differ.
TEST(AblationOptions, ContinuationNeverEndsAtAHigherEnergy) {
  const experiments::ProceduralShape cube =
      experiments::MakeShape(experiments::ParseShapeSpec("cube"));
  for (uint64_t seed : {1, 2}) {
    const experiments::SurfaceSamples clean = cube.Sample(2000, seed);
    experiments::NoiseOptions noise;
    noise.sigma = 0.01;
    noise.seed = seed + 100;
    const energy::PointList points =
        experiments::ApplyNoise(clean.points, clean.normals, noise).points;
    auto final_energy = [&](GncTarget target) {
      DenoiseOptions options = BaseOptions();
      options.minimizer.gnc.target = target;
      options.minimizer.max_iterations = 300;
      DenoiseState state = StartDenoising(points, options);
      const SolverSummary summary = MinimizeFromState(options, &state);
      EXPECT_EQ(summary.termination, TerminationType::kConvergence);
      return summary.final_energy.total();
    };
    const double plain = final_energy(GncTarget::kNone);
    EXPECT_LE(final_energy(GncTarget::kSmoothness), plain) << "seed " << seed;
    EXPECT_LE(final_energy(GncTarget::kBoth), plain) << "seed " << seed;
    EXPECT_NEAR(final_energy(GncTarget::kFitting), plain, 1e-5 * plain) << "seed " << seed;
  }
}

}  // namespace
}  // namespace lpd::solvers
