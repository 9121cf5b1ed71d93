// lpd denoise [INPUT] -o OUTPUT [flags]: the paper's method on a file, or on a built-in
// noisy box when no INPUT is given; --save-state / --resume stop and continue a run.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numeric>
#include <stdexcept>

#include <gflags/gflags.h>

#include "cli/commands.h"
#include "energy/wall_clock.h"
#include "cli/denoise_flags.h"
#include "cli/output_cloud.h"
#include "cli/run_summary.h"
#include "tiles/tiled_denoise.h"
#include "io/atomic_output_file.h"
#include "lpd/denoise.h"
#include "io/interruption.h"
#include "io/point_cloud_io.h"
#include "experiments/shapes/noise.h"
#include "experiments/shapes/shape_catalog.h"
#include "cli/denoise_state_file.h"
#include "solvers/denoise_point_set.h"

DEFINE_string(output, "",
              "output file (.ply or .pcd with normals and indicators, .las, .xyz, or .csv with "
              "a header line); also -o");
DEFINE_string(input_format, "",
              "format of INPUT (xyz, csv, ply, las, pcd, off, obj) when its extension does not "
              "say it; needed for '-', standard input");
DEFINE_string(output_format, "",
              "format of OUTPUT (ply, pcd, las, xyz, csv) when its extension does not say it; "
              "needed for '-o -', standard output (the summary then goes to stderr)");
DEFINE_bool(overwrite, false, "replace OUTPUT (and the --save_state file) if it already exists");
DEFINE_string(save_state, "",
              "after the iterations, save the optimizer's state (H, T, L, M, S, the k-NN "
              "graph, the parameters and Alg. 1's progress) to this file; also --save-state");
DEFINE_string(resume, "",
              "continue the run saved in this file instead of reading INPUT: no k-NN search, "
              "the saved parameters unless flags are given (not k or initialization), "
              "--max_iters more iterations; with the saved thread count the result is the "
              "same bit for bit as one uninterrupted run; no second outlier pass or "
              "isolation test (they need the input), and no offset feedback, thin-part "
              "steps or height smoothing (they need the noise estimate); also --resume=FILE");
DEFINE_string(summary_json, "",
              "also write what the run did to this JSON file: the parameters given and in "
              "effect, k, noise and spacing, the weights used, every pass, counts, times and "
              "the version");
DEFINE_bool(quiet, false, "do not print per-iteration progress");
DEFINE_bool(trace, false, "print the energy per term after every block update at the end");
DEFINE_uint64(seed, 1, "random seed of generated samples (and, plus one, of their noise)");
DEFINE_int32(default_points, 20000, "number of samples of the built-in default shape");
DEFINE_double(default_noise, 0.005,
              "Gaussian noise of the built-in shape, as a fraction of its bounding-box diagonal");
DEFINE_int32(tile_points, 0,
             "denoise in spatial tiles of at most this many points, each with a halo of its "
             "neighbours (0: one problem); under `mpirun -np R` the R processes share the tiles");
DEFINE_double(halo_radii, 3.0,
              "width of a tile's halo, in neighbourhood radii sqrt(k / pi) x spacing");

namespace lpd::cli {
namespace {

struct DefaultInput {
  experiments::ProceduralShape shape = experiments::MakeShape({"box", {}});
  energy::PointList points;
  double diagonal = 0.0;  // of the clean samples
};

DefaultInput MakeDefaultInput() {
  if (FLAGS_default_points < 1) throw std::invalid_argument("default_points must be >= 1");
  DefaultInput input;
  experiments::NoiseOptions noise;
  noise.sigma = FLAGS_default_noise;
  noise.seed = FLAGS_seed + 1;
  experiments::NoisyPointSet noisy =
      experiments::ApplyNoise(input.shape.Sample(FLAGS_default_points, FLAGS_seed).points, {}, noise);
  input.points = std::move(noisy.points);
  input.diagonal = noisy.scale_length;
  return input;
}

double MeanDistance(const experiments::ProceduralShape& shape, const energy::PointList& points) {
  double sum = 0.0;
  for (const energy::Point3& p : points) sum += shape.DistanceToSurface(p);
  return sum / static_cast<double>(points.size());
}

// One line per iteration (unless `quiet`): the energy per term, then the times of Alg. 1's
// two steps or, for the joint solve, the elapsed time and the linear solver's iterations.
// A pass after the first (a pass starts again at iteration 1) gets a line of its own.
// Returns false, and so stops the solver, once a signal has arrived.
solvers::IterationCallback ProgressPrinter(solvers::Solver solver, bool quiet) {
  auto last_iteration = std::make_shared<int>(0);
  auto pass = std::make_shared<int>(1);
  return [solver, quiet, last_iteration, pass](const solvers::IterationRecord& record) {
    if (quiet) return !io::InterruptionRequested();
    if (record.iteration <= *last_iteration) {
      std::fprintf(stderr, "pass %d: denoising the kept points again from their input\n",
                   ++*pass);
    }
    *last_iteration = record.iteration;
    std::fprintf(stderr, "iter %2d  energy %.6e (fit %.3e, smooth %.3e, stitch %.3e)  ",
                 record.iteration, record.energy.total(), record.energy.fitting,
                 record.energy.smoothness, record.energy.stitching);
    if (solver == solvers::Solver::kAlternating) {
      // The first iteration has no earlier output to have moved from.
      char move[32] = "-";
      if (!std::isnan(record.point_motion)) {
        std::snprintf(move, sizeof(move), "%.2e", record.point_motion);
      }
      std::fprintf(stderr, "move %s  local %.3f s  global %.3f s  cg %d\n", move,
                   record.local_seconds, record.global_seconds, record.cg_iterations);
    } else {
      std::fprintf(stderr, "elapsed %.3f s  linear iterations %d\n", record.elapsed_seconds,
                   record.cg_iterations);
    }
    return !io::InterruptionRequested();  // a signal stops the run after this iteration
  };
}

// The options and state a resumed run continues from, with the flags applied.
solvers::DenoiseState ResumeState(solvers::DenoiseOptions* options) {
  // What made the saved problem and start cannot change now (and the preset would only
  // restate parameters the state already fixes).
  for (const char* fixed : {"k", "k_radius_sigmas", "k_wide_noise", "max_k", "max_problem_size",
                            "far_factor", "merge_duplicates", "initialization",
                            "initialization_seed", "preset"}) {
    if (FlagGiven(fixed)) {
      throw std::invalid_argument(std::string("--") + fixed +
                                  " cannot change on --resume (the state fixes it)");
    }
  }
  SavedDenoiseRun saved = ReadDenoiseState(FLAGS_resume);
  *options = DenoiseOptionsFromFlags(&saved.parameters);
  if (!FlagGiven("threads")) {
    options->settings.num_threads = saved.num_threads;
  } else if (FLAGS_threads != saved.num_threads) {
    std::fprintf(stderr,
                 "note: the state was saved with %d threads; with %d the result can differ "
                 "in the last bits from an uninterrupted run\n",
                 saved.num_threads, FLAGS_threads);
  }
  // A new mu_l, or a new scale for it, is taken up again at the next local step.
  if (FlagGiven("mu_l") || FlagGiven("mu_l_noise_sigmas")) saved.state.progress.mu_l = NAN;
  std::fprintf(stderr, "resuming %s: %d points, k = %d, after %d iterations\n",
               FLAGS_resume.c_str(), saved.state.problem.num_points(), saved.state.problem.k(),
               saved.state.progress.iterations);
  return std::move(saved.state);
}

// True when `a` and `b` name the same file (also through another spelling or a link).
bool SameFile(const std::string& a, const std::string& b) {
  if (a == io::kStandardStream || b == io::kStandardStream) return false;  // stdin, stdout
  std::error_code error, error_a, error_b;
  if (a == b || std::filesystem::equivalent(a, b, error)) return true;
  // Files that do not exist yet: the same absolute path ("./s.xyz" and "s.xyz").
  const std::filesystem::path canonical_a =
      std::filesystem::weakly_canonical(std::filesystem::absolute(a, error_a), error_a);
  const std::filesystem::path canonical_b =
      std::filesystem::weakly_canonical(std::filesystem::absolute(b, error_b), error_b);
  return !error_a && !error_b && canonical_a == canonical_b;
}

// Refuses, before any work, outputs that would replace an input, collide, have no known
// format, or cannot be written. --overwrite lets --save_state update the state it resumed
// from, and nothing else that is an input.
void CheckOutputs(const std::string& input, bool resume) {
  const bool updates_state = resume && FLAGS_save_state == FLAGS_resume && FLAGS_overwrite;
  if (!input.empty() && ((!FLAGS_output.empty() && SameFile(FLAGS_output, input)) ||
                         (!FLAGS_save_state.empty() && SameFile(FLAGS_save_state, input) &&
                          !updates_state))) {
    throw std::invalid_argument("output " + input + " is also an input (refusing to overwrite it)");
  }
  const std::pair<const char*, const std::string*> outputs[] = {
      {"-o", &FLAGS_output}, {"--save_state", &FLAGS_save_state},
      {"--summary_json", &FLAGS_summary_json}};
  for (size_t a = 0; a < std::size(outputs); ++a) {
    for (size_t b = a + 1; b < std::size(outputs); ++b) {
      if (!outputs[a].second->empty() && !outputs[b].second->empty() &&
          SameFile(*outputs[a].second, *outputs[b].second)) {
        throw std::invalid_argument(std::string(outputs[a].first) + " and " +
                                    outputs[b].first + " name the same file");
      }
    }
  }
  if (!FLAGS_summary_json.empty()) {
    if (!input.empty() && SameFile(FLAGS_summary_json, input)) {
      throw std::invalid_argument("output " + input +
                                  " is also an input (refusing to overwrite it)");
    }
    io::RefuseExistingOutput(FLAGS_summary_json, FLAGS_overwrite);
  }
  if (!FLAGS_output.empty()) {
    io::OutputFormat(FLAGS_output, FLAGS_output_format);
    io::RefuseExistingOutput(FLAGS_output, FLAGS_overwrite);
  }
  if (!FLAGS_save_state.empty()) io::RefuseExistingOutput(FLAGS_save_state, FLAGS_overwrite);
}

// The points to denoise: INPUT's (and its normals, if it has them), or the built-in box.
struct DenoiseInput {
  DefaultInput built_in;          // when no INPUT is given
  bool is_built_in = false;
  energy::PointList points;       // kept for further passes without the outliers
  energy::PointList normals;      // from an input with normals
  io::PointCloud properties;      // the input's attributes and LAS header (no points)

  const energy::PointList* normals_or_null() const { return normals.empty() ? nullptr : &normals; }
};

DenoiseInput LoadInput(const std::vector<std::string>& arguments) {
  DenoiseInput input;
  if (!arguments.empty()) {
    io::PointCloud cloud = io::ReadPointCloud(arguments[0], FLAGS_input_format);
    if (cloud.skipped_points > 0) {
      std::fprintf(stderr, "%s: %zu points with a NaN coordinate (no return) left out\n",
                   arguments[0].c_str(), cloud.skipped_points);
    }
    input.points = std::move(cloud.points);
    input.normals = std::move(cloud.normals);
    input.properties.attributes = std::move(cloud.attributes);
    input.properties.las = std::move(cloud.las);
    input.properties.float_coordinates = cloud.float_coordinates;
    return input;
  }
  input.is_built_in = true;
  input.built_in = MakeDefaultInput();
  std::fprintf(stderr,
               "no INPUT given: denoising the built-in %s, %d points, Gaussian noise "
               "%.2f%% of the bounding-box diagonal, seed %llu\n",
               input.built_in.shape.description().c_str(), FLAGS_default_points,
               100.0 * FLAGS_default_noise, static_cast<unsigned long long>(FLAGS_seed));
  input.points = input.built_in.points;
  return input;
}

// The feature points among the output points (the count over all points includes removed
// outliers).
int KeptFeatures(const solvers::DenoiseResult& result) {
  int count = 0;
  for (size_t i = 0; i < result.kept.size(); ++i) {
    count += result.kept[i] && result.indicators.is_feature[i];
  }
  return count;
}

// Where the summary goes: stdout, or stderr when stdout carries the output ("-o -").
std::FILE* Report() { return FLAGS_output == io::kStandardStream ? stderr : stdout; }

// " (N repeated points merged)" when the input repeated points, exactly or nearly.
std::string DuplicatesNote(const solvers::DenoiseResult& result) {
  std::string note;
  if (result.num_duplicates > 0) note = std::to_string(result.num_duplicates) + " repeated";
  if (result.num_near_repeats > 0) {
    note += (note.empty() ? "" : " and ") + std::to_string(result.num_near_repeats) +
            " nearly repeated";
  }
  return note.empty() ? "" : " (" + note + " points merged)";
}

// The run's summary on stdout (stderr for the solver's brief report and notes).
void PrintSummary(const solvers::DenoiseResult& result, const solvers::DenoiseOptions& options,
                  size_t num_input_points, size_t num_output_points) {
  std::fprintf(stderr, "%s\n", result.summary.BriefReport().c_str());
  if (!result.removal_note.empty()) std::fprintf(stderr, "note: %s\n", result.removal_note.c_str());
  std::fprintf(Report(), 
      "points in %zu%s, out %zu, outliers flagged %d (%d isolated, %d far), removed %d, "
      "feature points %d, iterations %d, passes %d, time %.2f s (k-NN %.2f s)\n",
      num_input_points, DuplicatesNote(result).c_str(), num_output_points, result.num_outliers,
      result.num_isolated,
      result.num_far, result.num_removed, KeptFeatures(result), result.summary.num_iterations, result.passes,
      result.total_seconds, result.setup_seconds);
  std::string chosen;
  if (result.neighborhood.spacing > 0.0) {
    const solvers::NeighborhoodSize& size = result.neighborhood;
    char text[300];
    std::snprintf(text, sizeof(text),
                  " (from noise %.3g as the probe reads it, %.3g estimated, and spacing %.3g of "
                  "the diagonal: radius %.3g readings)",
                  size.read_sigma, size.noise_sigma, size.spacing, size.radius_in_sigmas);
    chosen = text;
    if (size.merged_sides) {
      std::snprintf(text, sizeof(text),
                    " (from the spread %.3g of merged sides of a thin part, noise %.3g each, and "
                    "spacing %.3g of the diagonal: radius %.3g spreads)",
                    size.read_sigma, size.noise_sigma, size.spacing, size.radius_in_sigmas);
      chosen = text;
    }
  }
  if (result.subsampled) {
    chosen += " on a subsample of " + std::to_string(result.solved_points) + " points";
  }
  std::fprintf(Report(), "k %d%s, eta %.4g, lambda %.4g, mu_l %.4g, mu_m %.4g\n", result.neighborhood.k,
              chosen.c_str(), result.summary.eta, result.summary.lambda, result.summary.mu_l,
              options.settings.energy.mu_m);
  if (options.final_step.snap_features) {
    std::fprintf(Report(), "feature points snapped: %d onto edges, %d at corners, %d left on their plane\n",
                result.snapping.snapped_to_edge, result.snapping.snapped_at_corner,
                result.snapping.left_on_plane);
  }
}

// How much closer to the clean built-in box the output is than the input.
void PrintBuiltInDistance(const DefaultInput& built_in, const energy::PointList& output) {
  const double diagonal = built_in.diagonal;
  const double before = MeanDistance(built_in.shape, built_in.points);
  const double after = MeanDistance(built_in.shape, output);
  std::fprintf(Report(), 
      "mean distance to the clean box: input %.3e, output %.3e (/diagonal: %.3e -> %.3e, "
      "%.1fx %s)\n",
      before, after, before / diagonal, after / diagonal,
      after <= before ? before / after : after / before, after <= before ? "lower" : "higher");
}

// The tiled run (tiled_denoise.h): rank 0 reads INPUT and writes the output.
int RunTiled(const std::vector<std::string>& arguments, const solvers::DenoiseOptions& options,
             const solvers::TilingOptions& tiling) {
  DenoiseInput built_in;
  if (arguments.empty()) built_in = LoadInput(arguments);
  const tiles::TiledRun run =
      tiles::DenoiseInTiles(arguments.empty() ? "" : arguments[0], built_in.points, options, tiling,
                     FLAGS_output, FLAGS_overwrite, FlagGiven("threads"), FLAGS_quiet);
  if (!run.is_root) return 0;
  std::fprintf(Report(), 
      "points in %zu, out %ld, outliers flagged %ld, removed %ld, feature points %ld, "
      "time %.2f s\n",
      run.num_points, run.kept, run.outliers, static_cast<long>(run.num_points) - run.kept,
      run.features, run.seconds);
  std::fprintf(Report(), "tiles %d on %d process%s x %d thread%s, halo points %ld, k %d-%d, at most %d "
              "iterations, %d of %d tiles converged\n",
              run.tiles, run.ranks, run.ranks > 1 ? "es" : "", run.threads_per_rank,
              run.threads_per_rank > 1 ? "s" : "", run.halo_points, run.min_k, run.max_k,
              run.max_iterations, run.converged_tiles, run.tiles);
  if (!FLAGS_output.empty()) std::fprintf(Report(), "wrote %s\n", FLAGS_output.c_str());
  return 0;
}

}  // namespace

int RunDenoiseCommand(const std::vector<std::string>& arguments) {
  if (arguments.size() > 1) {
    throw std::invalid_argument("denoise takes at most one INPUT file, got " +
                                std::to_string(arguments.size()));
  }
  const bool resume = !FLAGS_resume.empty();
  if (resume && !arguments.empty()) {
    throw std::invalid_argument("give either INPUT or --resume, not both");
  }
  solvers::DenoiseOptions options;
  solvers::DenoiseState state;
  if (resume) state = ResumeState(&options);
  else options = DenoiseOptionsFromFlags();
  options.minimizer.trace_blocks = FLAGS_trace;  // per-block energies cost a pass each
  if (!arguments.empty() || resume) {
    if (FLAGS_output.empty() && FLAGS_save_state.empty()) {
      throw std::invalid_argument("missing output file: give -o OUTPUT (or --save_state)");
    }
  }
  CheckOutputs(resume ? FLAGS_resume : arguments.empty() ? "" : arguments[0], resume);

  const solvers::TilingOptions tiling{FLAGS_tile_points, FLAGS_halo_radii};
  std::string invalid;
  if (!tiling.IsValid(&invalid)) throw std::invalid_argument(invalid);
  if (tiling.tile_points > 0) {
    if (resume || !FLAGS_save_state.empty()) {
      throw std::invalid_argument("--tile_points cannot be combined with --save_state or --resume");
    }
    if ((!arguments.empty() && arguments[0] == io::kStandardStream) ||
        FLAGS_output == io::kStandardStream || !FLAGS_input_format.empty() ||
        !FLAGS_output_format.empty()) {
      throw std::invalid_argument(
          "--tile_points reads and writes named files with their extensions (no '-', "
          "--input_format or --output_format)");
    }
    if (options.EffectiveInitialization() == solvers::Initialization::kInputNormals) {
      throw std::invalid_argument(
          "--tile_points cannot be combined with --initialization=input_normals (tiles read "
          "points only)");
    }
    const std::string format = FLAGS_output.empty() ? "ply" : io::OutputFormat(FLAGS_output, "");
    if (format == "pcd") {
      throw std::invalid_argument("--tile_points writes its output point by point: give a .ply, "
                                  ".las or .xyz output (PCD is written whole)");
    }
    return RunTiled(arguments, options, tiling);
  }
  const Clock::time_point start = Clock::now();
  solvers::DenoiseHooks hooks;
  hooks.progress = ProgressPrinter(options.solver, FLAGS_quiet);
  if (!FLAGS_save_state.empty()) {
    hooks.on_minimized = [&options](const solvers::DenoiseState& minimized) {
      io::ThrowIfInterrupted();  // an interrupted run saves no state
      WriteDenoiseState(FLAGS_save_state, minimized, options, FLAGS_overwrite);
    };
  }
  DenoiseInput input;
  solvers::DenoiseResult result;
  if (resume) {
    result = solvers::ContinueDenoising(std::move(state), options, hooks);
  } else {
    input = LoadInput(arguments);
    io::ThrowIfInterrupted();
    result = solvers::DenoisePointSet(input.points, options, hooks, input.normals_or_null());
  }
  io::ThrowIfInterrupted();
  result.total_seconds = SecondsSince(start);
  if (FLAGS_trace) std::fprintf(stderr, "%s", result.summary.FullReport().c_str());

  RunDescription run;
  run.version = Version();
  run.input = resume ? FLAGS_resume : arguments.empty() ? "built-in box" : arguments[0];
  run.output = FLAGS_output;
  run.preset = FLAGS_preset;
  run.given = GivenParameters();
  const std::string format =
      FLAGS_output.empty() ? "ply" : io::OutputFormat(FLAGS_output, FLAGS_output_format);
  io::PointCloud cloud = MakeOutputCloud(
      result, input.properties,
      format == "ply" || format == "pcd" ? OutputKind::kPly
      : format == "las"                  ? OutputKind::kLas
                                         : OutputKind::kText);
  cloud.comments = RunHeaderComments(run, options, result);
  if (!FLAGS_output.empty()) {
    io::WritePointCloud(FLAGS_output, cloud, FLAGS_overwrite, FLAGS_output_format);
  }
  if (!FLAGS_summary_json.empty()) {
    io::AtomicOutputFile summary(FLAGS_summary_json, FLAGS_overwrite);
    summary.stream() << RunSummaryJson(run, options, result, cloud.points.size()) << "\n";
    summary.Commit();
  }
  PrintSummary(result, options, result.projected.size(), cloud.points.size());
  if (input.is_built_in) PrintBuiltInDistance(input.built_in, cloud.points);
  if (!FLAGS_save_state.empty()) std::fprintf(Report(), "saved state %s\n", FLAGS_save_state.c_str());
  if (!FLAGS_output.empty()) std::fprintf(Report(), "wrote %s\n", FLAGS_output.c_str());
  if (!FLAGS_summary_json.empty()) std::fprintf(Report(), "wrote %s\n", FLAGS_summary_json.c_str());
  return 0;
}

}  // namespace lpd::cli
