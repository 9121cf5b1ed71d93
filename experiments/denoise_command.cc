// lpd denoise [INPUT] -o OUTPUT [flags]: the paper's method on a file, or on a built-in
// noisy box when no INPUT is given.
#include <algorithm>
#include <cstdio>
#include <numeric>
#include <stdexcept>

#include <gflags/gflags.h>

#include "experiments/commands.h"
#include "experiments/denoise_flags.h"
#include "experiments/noise.h"
#include "experiments/point_cloud_io.h"
#include "experiments/shape_catalog.h"
#include "solvers/denoise_point_set.h"

DEFINE_string(output, "", "output file (.ply with normals and indicators, or .xyz); also -o");
DEFINE_bool(overwrite, false, "replace OUTPUT if it already exists");
DEFINE_bool(quiet, false, "do not print per-iteration progress");
DEFINE_bool(trace, false, "print the energy per term after every block update at the end");
DEFINE_uint64(seed, 1, "random seed of generated samples (and, plus one, of their noise)");
DEFINE_int32(default_points, 20000, "number of samples of the built-in default shape");
DEFINE_double(default_noise, 0.005,
              "Gaussian noise of the built-in shape, as a fraction of its bounding-box diagonal");

namespace lpd::experiments {
namespace {

struct DefaultInput {
  ProceduralShape shape = MakeShape({"box", {}});
  energy::PointList points;
  double diagonal = 0.0;  // of the clean samples
};

DefaultInput MakeDefaultInput() {
  if (FLAGS_default_points < 1) throw std::invalid_argument("default_points must be >= 1");
  DefaultInput input;
  NoiseOptions noise;
  noise.sigma = FLAGS_default_noise;
  noise.seed = FLAGS_seed + 1;
  NoisyPointSet noisy =
      ApplyNoise(input.shape.Sample(FLAGS_default_points, FLAGS_seed).points, {}, noise);
  input.points = std::move(noisy.points);
  input.diagonal = noisy.scale_length;
  return input;
}

double MeanDistance(const ProceduralShape& shape, const energy::PointList& points) {
  double sum = 0.0;
  for (const energy::Point3& p : points) sum += shape.DistanceToSurface(p);
  return sum / static_cast<double>(points.size());
}

// One line per iteration: the energy per term, then the times of Alg. 1's two steps or, for
// the joint solve, the elapsed time and the linear solver's iterations.
solvers::IterationCallback ProgressPrinter(solvers::Solver solver) {
  return [solver](const solvers::IterationRecord& record) {
    std::fprintf(stderr, "iter %2d  energy %.6e (fit %.3e, smooth %.3e, stitch %.3e)  ",
                 record.iteration, record.energy.total(), record.energy.fitting,
                 record.energy.smoothness, record.energy.stitching);
    if (solver == solvers::Solver::kAlternating) {
      std::fprintf(stderr, "local %.3f s  global %.3f s  cg %d\n", record.local_seconds,
                   record.global_seconds, record.cg_iterations);
    } else {
      std::fprintf(stderr, "elapsed %.3f s  linear iterations %d\n", record.elapsed_seconds,
                   record.cg_iterations);
    }
    return true;
  };
}

PointCloud MakeOutputCloud(const solvers::DenoiseResult& result) {
  PointCloud cloud;
  std::vector<float> source_index, outlier, outlier_score, feature, feature_score;
  for (size_t i = 0; i < result.projected.size(); ++i) {
    if (!result.kept[i]) continue;
    source_index.push_back(static_cast<float>(i));
    cloud.points.push_back(result.projected[i]);
    cloud.normals.push_back(result.normals[i]);
    outlier.push_back(result.indicators.is_outlier[i]);
    outlier_score.push_back(static_cast<float>(result.indicators.outlier_score[i]));
    feature.push_back(result.indicators.is_feature[i]);
    feature_score.push_back(static_cast<float>(result.indicators.feature_score[i]));
  }
  cloud.scalars = {{"source_index", source_index},
                   {"outlier", outlier},
                   {"outlier_score", outlier_score},
                   {"feature", feature},
                   {"feature_score", feature_score}};
  return cloud;
}

}  // namespace

int RunDenoiseCommand(const std::vector<std::string>& arguments) {
  if (arguments.size() > 1) {
    throw std::invalid_argument("denoise takes at most one INPUT file, got " +
                                std::to_string(arguments.size()));
  }
  solvers::DenoiseOptions options = DenoiseOptionsFromFlags();
  options.minimizer.trace_blocks = FLAGS_trace;  // per-block energies cost a pass each
  const bool use_default = arguments.empty();
  if (!use_default && FLAGS_output.empty()) {
    throw std::invalid_argument("missing output file: give -o OUTPUT");
  }
  if (!use_default && FLAGS_output == arguments[0]) {
    throw std::invalid_argument("OUTPUT must differ from INPUT (refusing to overwrite input)");
  }
  if (!FLAGS_output.empty()) {
    const std::string extension = FileExtension(FLAGS_output);
    if (extension != "ply" && extension != "xyz" && extension != "txt") {
      throw std::invalid_argument("output extension must be .ply, .xyz or .txt: " +
                                  FLAGS_output);
    }
  }

  DefaultInput default_input;
  energy::PointList input;
  if (use_default) {
    default_input = MakeDefaultInput();
    input = default_input.points;
    std::fprintf(stderr,
                 "no INPUT given: denoising the built-in %s, %d points, Gaussian noise "
                 "%.2f%% of the bounding-box diagonal, seed %llu\n",
                 default_input.shape.description().c_str(), FLAGS_default_points,
                 100.0 * FLAGS_default_noise,
                 static_cast<unsigned long long>(FLAGS_seed));
  } else {
    input = ReadPoints(arguments[0]);
  }

  const solvers::DenoiseResult result = solvers::DenoisePointSet(
      input, options,
      FLAGS_quiet ? solvers::IterationCallback() : ProgressPrinter(options.solver));
  if (FLAGS_trace) std::fprintf(stderr, "%s", result.summary.FullReport().c_str());

  const PointCloud cloud = MakeOutputCloud(result);
  if (!FLAGS_output.empty()) WritePointCloud(FLAGS_output, cloud, FLAGS_overwrite);

  std::fprintf(stderr, "%s\n", result.summary.BriefReport().c_str());
  if (!result.removal_note.empty()) std::fprintf(stderr, "note: %s\n", result.removal_note.c_str());
  std::printf(
      "points in %zu, out %zu, outliers flagged %d, removed %d, feature points %d, "
      "iterations %d, time %.2f s (k-NN %.2f s)\n",
      input.size(), cloud.points.size(), result.num_outliers, result.num_removed,
      result.num_features, result.summary.num_iterations, result.total_seconds,
      result.setup_seconds);
  if (use_default) {
    const double diagonal = default_input.diagonal;
    const double before = MeanDistance(default_input.shape, input);
    const double after = MeanDistance(default_input.shape, cloud.points);
    std::printf(
        "mean distance to the clean box: input %.3e, output %.3e (/diagonal: %.3e -> %.3e, "
        "%.1fx %s)\n",
        before, after, before / diagonal, after / diagonal,
        after <= before ? before / after : after / before, after <= before ? "lower" : "higher");
  }
  if (!FLAGS_output.empty()) std::printf("wrote %s\n", FLAGS_output.c_str());
  return 0;
}

}  // namespace lpd::experiments
