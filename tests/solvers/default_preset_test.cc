// The default method (lpd/presets.h) minimizes an energy whose weights come from the
// data: it converges before max_iters, more iterations do not make it worse, and the same
// cloud at another scale gives the same result.
#include "lpd/presets.h"

#include <iterator>

#include <gtest/gtest.h>

#include "experiments/shapes/noise.h"
#include "experiments/shapes/shape_catalog.h"
#include "solvers/denoise_point_set.h"

namespace lpd::solvers {
namespace {

struct NoisyShape {
  experiments::ProceduralShape shape;
  energy::PointList points;
};

NoisyShape NoisyCadPart(int n, double sigma, double outlier_ratio = 0.0,
                        uint64_t sample_seed = 2) {
  NoisyShape noisy{experiments::MakeShape({"cad_part", {}}), {}};
  experiments::NoiseOptions noise;
  noise.sigma = sigma;
  noise.outlier_ratio = outlier_ratio;
  noise.seed = sample_seed + 1;
  noisy.points =
      experiments::ApplyNoise(noisy.shape.Sample(n, sample_seed).points, {}, noise).points;
  return noisy;
}

// Mean distance of the kept output points to the clean shape, with every point divided by
// `scale` first.
double MeanDistance(const experiments::ProceduralShape& shape, const DenoiseResult& result,
                    double scale = 1.0) {
  double sum = 0.0;
  int kept = 0;
  for (size_t i = 0; i < result.projected.size(); ++i) {
    if (!result.kept[i]) continue;
    sum += shape.DistanceToSurface(result.projected[i] / scale);
    ++kept;
  }
  return sum / kept;
}

DenoiseOptions Defaults() {
  DenoiseOptions options = PresetOptions(Preset::kDefault);
  options.settings.num_threads = 2;
  return options;
}

TEST(DefaultPreset, ConvergesAndMoreIterationsDoNotMakeItWorse) {
  const NoisyShape noisy = NoisyCadPart(4000, 0.005);
  DenoiseOptions options = Defaults();
  const DenoiseResult stopped = DenoisePointSet(noisy.points, options);
  ASSERT_EQ(stopped.summary.termination, TerminationType::kConvergence)
      << stopped.summary.message;
  EXPECT_LT(stopped.summary.num_iterations, options.minimizer.max_iterations);

  options.minimizer.energy_tolerance = 0.0;  // all 50 iterations
  options.minimizer.progress_tolerance = 0.0;
  options.minimizer.motion_tolerance = 0.0;
  options.minimizer.max_iterations = 50;
  const DenoiseResult run_on = DenoisePointSet(noisy.points, options);
  ASSERT_EQ(run_on.summary.num_iterations, options.minimizer.max_iterations);
  // After the first iteration fixes mu_l, every iteration lowers one and the same energy.
  const std::vector<IterationRecord>& records = run_on.summary.iterations;
  for (size_t t = 2; t < records.size(); ++t) {
    EXPECT_LE(records[t].energy.total(), records[t - 1].energy.total() * (1.0 + 1e-9))
        << "iteration " << records[t].iteration;
  }
  double input = 0.0;
  for (const energy::Point3& p : noisy.points) input += noisy.shape.DistanceToSurface(p);
  input /= noisy.points.size();
  const double at_stop = MeanDistance(noisy.shape, stopped);
  const double at_50 = MeanDistance(noisy.shape, run_on);
  EXPECT_LT(at_stop, 0.5 * input);
  EXPECT_LE(at_50, 1.02 * at_stop) << "stopped after " << stopped.summary.num_iterations;
}

TEST(DefaultPreset, TheSameCloudAtAnotherScaleGivesTheSameResult) {
  const NoisyShape noisy = NoisyCadPart(4000, 0.005);
  constexpr double kScale = 1000.0;
  energy::PointList scaled = noisy.points;
  for (energy::Point3& p : scaled) p *= kScale;
  const DenoiseOptions options = Defaults();
  const DenoiseResult original = DenoisePointSet(noisy.points, options);
  const DenoiseResult enlarged = DenoisePointSet(scaled, options);
  EXPECT_NEAR(enlarged.summary.mu_l, original.summary.mu_l, 1e-6 * original.summary.mu_l);
  EXPECT_NEAR(MeanDistance(noisy.shape, enlarged, kScale), MeanDistance(noisy.shape, original),
              0.01 * MeanDistance(noisy.shape, original));
}

TEST(DefaultPreset, ADenserSamplingGetsMoreNeighboursAndNoWorseResult) {
  const NoisyShape sparse = NoisyCadPart(4000, 0.005);
  const NoisyShape dense = NoisyCadPart(16000, 0.005);
  const DenoiseOptions options = Defaults();
  const DenoiseState sparse_state = StartDenoising(sparse.points, options);
  const DenoiseState dense_state = StartDenoising(dense.points, options);
  // Same noise, half the spacing: more neighbours for the same neighbourhood radius. (Not
  // the full 4x: at the sparser sampling the probe's residuals carry more curvature, which
  // raises the noise estimate; measured 12 and 20 here.)
  EXPECT_NEAR(dense_state.neighborhood.spacing, 0.5 * sparse_state.neighborhood.spacing,
              0.1 * sparse_state.neighborhood.spacing);
  EXPECT_GT(dense_state.problem.k(), sparse_state.problem.k());
  const DenoiseResult sparse_result = DenoisePointSet(sparse.points, options);
  const DenoiseResult dense_result = DenoisePointSet(dense.points, options);
  EXPECT_LE(MeanDistance(dense.shape, dense_result), MeanDistance(sparse.shape, sparse_result));
}

// Past the problem-size budget (thinning.h) the result hardly depends on the density: the
// solved subsample is the same size. A draw of 20,000 points differs from another draw by up
// to 3% (the subsample holds 12,000), so each side averages three draws. What remains is
// that points left out of the subsample come out about 2.5% farther from the surface than
// solved ones, and 85% of the dense cloud is left out against 42% of the sparse one
// (measured: 3.667e-3 against 3.591e-3, 2.1%).
TEST(DefaultPreset, PastTheBudgetA4xDenserCloudAtAnotherScaleGivesTheSameResult) {
  constexpr double kScale = 1000.0;
  constexpr uint64_t kDraws[] = {2, 4, 6};
  DenoiseOptions options = Defaults();
  options.neighborhood.max_problem_size = 5e5;
  double sparse = 0.0, dense = 0.0;
  for (uint64_t seed : kDraws) {
    const NoisyShape sparse_cloud = NoisyCadPart(20000, 0.01, 0.0, seed);
    NoisyShape dense_cloud = NoisyCadPart(80000, 0.01, 0.0, seed);
    for (energy::Point3& p : dense_cloud.points) p *= kScale;
    const DenoiseResult sparse_result = DenoisePointSet(sparse_cloud.points, options);
    const DenoiseResult dense_result = DenoisePointSet(dense_cloud.points, options);
    EXPECT_LT(sparse_result.solved_points, 13000);
    EXPECT_NEAR(dense_result.solved_points, sparse_result.solved_points,
                0.05 * sparse_result.solved_points);
    sparse += MeanDistance(sparse_cloud.shape, sparse_result) / std::size(kDraws);
    dense += MeanDistance(dense_cloud.shape, dense_result, kScale) / std::size(kDraws);
  }
  EXPECT_NEAR(dense, sparse, 0.02 * sparse);  // measured: 0.4%
}

TEST(DefaultPreset, ASecondPassWithoutTheOutliersGivesTheOutlierFreeResult) {
  const NoisyShape clean = NoisyCadPart(6000, 0.004);
  const NoisyShape with_outliers = NoisyCadPart(6000, 0.004, 0.2);  // the same points first
  DenoiseOptions options = Defaults();
  const double outlier_free = MeanDistance(clean.shape, DenoisePointSet(clean.points, options));
  const DenoiseResult isolation_too = DenoisePointSet(with_outliers.points, options);
  options.final_step.isolation.radius_factor = 0.0;  // the passes alone
  const DenoiseResult two_passes = DenoisePointSet(with_outliers.points, options);
  options.final_step.outlier_passes = 1;
  const DenoiseResult one_pass = DenoisePointSet(with_outliers.points, options);
  EXPECT_EQ(two_passes.passes, 2);
  EXPECT_EQ(one_pass.passes, 1);
  // The second pass only removes more: every point removed by the first stays removed.
  int removed_once = 0;
  for (size_t i = 0; i < one_pass.kept.size(); ++i) {
    removed_once += !one_pass.kept[i];
    if (!one_pass.kept[i]) {
      EXPECT_FALSE(two_passes.kept[i]) << "point " << i;
    }
  }
  EXPECT_GT(two_passes.num_removed, removed_once);
  const double first = MeanDistance(with_outliers.shape, one_pass);
  const double second = MeanDistance(with_outliers.shape, two_passes);
  const double isolated_removed = MeanDistance(with_outliers.shape, isolation_too);
  // Measured (6,000 points): one pass 2.43x the outlier-free distance, two passes 1.51x, and
  // 1.08x with the isolated points removed too; with the plain mean of the blended surfaces
  // 1.46x and 1.06x, the outlier-free run then 3% farther from the surface and the two-pass
  // one 0.3% nearer (at 25,000 points 1.10x and 1.01x, docs/method.md). The isolation test
  // only removes points: the others keep their results.
  EXPECT_LT(second, 0.75 * first);
  EXPECT_LT(second, 1.6 * outlier_free) << "one pass: " << first / outlier_free << "x";
  EXPECT_GT(isolation_too.num_isolated, 0);
  EXPECT_EQ(isolation_too.num_removed, two_passes.num_removed + isolation_too.num_isolated);
  for (size_t i = 0; i < two_passes.kept.size(); ++i) {
    if (!isolation_too.kept[i]) continue;
    EXPECT_TRUE(two_passes.kept[i]) << "point " << i;
    EXPECT_EQ(isolation_too.projected[i], two_passes.projected[i]) << "point " << i;
  }
  EXPECT_LT(isolated_removed, 0.85 * second)
      << "two passes " << second / outlier_free << "x, isolation too "
      << isolated_removed / outlier_free << "x the outlier-free distance";
}

}  // namespace
}  // namespace lpd::solvers
