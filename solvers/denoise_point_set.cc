#include "solvers/denoise_point_set.h"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <vector>

#include <unistd.h>

#include "energy/spatial_order.h"
#include "energy/wall_clock.h"
#include "solvers/duplicate_points.h"
#include "solvers/even_spacing.h"
#include "solvers/far_points.h"
#include "solvers/adaptive_heights.h"
#include "solvers/height_smoothing.h"
#include "solvers/between_layers.h"
#include "solvers/merged_sides.h"
#include "solvers/near_repeats.h"
#include "solvers/offset_feedback.h"
#include "solvers/parse_by_name.h"
#include "solvers/residual_statistics.h"
#include "solvers/sphere_projection.h"
#include "solvers/subsample_extension.h"
#include "solvers/thinning.h"

namespace lpd::solvers {
namespace {

// values[r] belongs to input point order[r], extended[e] to input point left_out[e]; returns
// them indexed by input point.
template <typename Values>
Values ToInputOrder(const Values& values, const std::vector<int>& order, const Values& extended,
                    const std::vector<int>& left_out) {
  Values input_ordered(values.size() + extended.size());
  for (size_t r = 0; r < order.size(); ++r) input_ordered[order[r]] = values[r];
  for (size_t e = 0; e < left_out.size(); ++e) input_ordered[left_out[e]] = extended[e];
  return input_ordered;
}

// values[i] belongs to input point i; returns them in problem order (row r: order[r]).
template <typename Values>
Values ToProblemOrder(const Values& values, const std::vector<int>& order) {
  Values ordered(order.size());
  for (size_t r = 0; r < order.size(); ++r) ordered[r] = values[order[r]];
  return ordered;
}

// Peak memory of a run on n points at k neighbours, from the figures measured on cad_part
// (docs/performance.md): 1.39 KB per point at k = 20 and 4.9 KB at k = 91.
double EstimatedPeakBytes(double n, double k) { return n * (400.0 + 49.4 * k); }

// Refuses a run that cannot fit in this machine's physical memory before allocating it.
void CheckFitsInMemory(int n, int k) {
  const double available =
      static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGESIZE));
  const double needed = EstimatedPeakBytes(n, k);
  if (available > 0.0 && needed > available) {
    char message[256];
    std::snprintf(message, sizeof(message),
                  "k = %d on %d points needs about %.1f GB, more than this machine's %.1f GB "
                  "(give a smaller --k or --max_k)",
                  k, n, needed / 1e9, available / 1e9);
    throw std::invalid_argument(message);
  }
}

// Keeps the rows `solved` (increasing) of `ordered_points` as the problem's points and
// order, and moves the others to state->left_out.
void SplitOffUnsolved(const std::vector<int>& solved, const energy::PointList& ordered_points,
                      DenoiseState* state, energy::PointList* solved_points) {
  std::vector<int> solved_order;
  solved_order.reserve(solved.size());
  solved_points->clear();
  solved_points->reserve(solved.size());
  size_t next = 0;
  for (size_t r = 0; r < ordered_points.size(); ++r) {
    if (next < solved.size() && solved[next] == static_cast<int>(r)) {
      solved_order.push_back(state->order[r]);
      solved_points->push_back(ordered_points[r]);
      ++next;
    } else {
      state->left_out.push_back(state->order[r]);
      state->left_out_points.push_back(ordered_points[r]);
    }
  }
  state->order = std::move(solved_order);
}

// One set of points whose merged sides are told apart: `inputs` (normalized frame) and their
// `outputs` (input frame, moved in place).
struct SidesInput {
  const energy::PointList& inputs;
  const energy::PointList& normals;
  const std::vector<uint8_t>& is_outlier;
  energy::PointList* outputs;
};

// The points the between-layers step moved are spread again where they are at least this
// share of the solved points: on the benchmark's thin parts it moved 67-99% of them (the
// layers' heights corrected everywhere), and spread, their P2M went down by up to 0.08 x
// 1e-4; where it moved 2-19% (JOINT 0.03 and FANDISK 0.03 of Table 1, plate_t0.06 50K 3%,
// sheets_gap0.04 50K 2%) the moved points lie scattered, and spread, those clouds came out
// the same or up to 0.004 higher (docs/method.md, "The layers' points spread again").
constexpr double kMinLayeredShareToSpread = 0.5;

// SeparateMergedSides over all `sets` at once, then, with `read_layers`,
// MoveBetweenLayerPointsOntoLayers in each (points between the layers moved with
// `move_between`), the flagged outliers standing; returns how many points moved, and flags in
// `split` the points of the first set that SeparateMergedSides moved, in `layered_only` the
// others of that set that MoveBetweenLayerPointsOntoLayers moved. Each step is a lap of
// `clock` ("merged sides", "layers").
int SeparateSides(const energy::Frame& frame, const std::vector<SidesInput>& sets,
                  bool read_layers, bool move_between, int num_threads, StageClock* clock,
                  std::vector<uint8_t>* split, std::vector<uint8_t>* layered_only) {
  std::vector<energy::PointList> normalized(sets.size());
  std::vector<std::vector<uint8_t>> movable(sets.size());
  std::vector<SidesPart> parts;
  for (size_t s = 0; s < sets.size(); ++s) {
    const energy::PointList& outputs = *sets[s].outputs;
    normalized[s].resize(outputs.size());
    movable[s].resize(outputs.size());
    for (size_t i = 0; i < outputs.size(); ++i) {
      normalized[s][i] = frame.ToNormalized(outputs[i]);
      movable[s][i] = !sets[s].is_outlier[i];
    }
    parts.push_back({sets[s].inputs, normalized[s], sets[s].normals, movable[s]});
  }
  int moved = 0;
  const std::vector<energy::PointList> separated =
      SeparateMergedSides(parts, num_threads, &moved);
  clock->Lap("merged sides");
  split->assign(separated[0].size(), 0);
  for (size_t i = 0; i < separated[0].size(); ++i) {
    (*split)[i] = separated[0][i] != normalized[0][i];
  }
  for (size_t s = 0; s < sets.size(); ++s) {
    int between = 0;
    const energy::PointList layered =
        read_layers ? MoveBetweenLayerPointsOntoLayers(sets[s].inputs, separated[s],
                                                       sets[s].normals, movable[s], move_between,
                                                       num_threads, &between)
                    : separated[s];
    moved += between;
    for (size_t i = 0; i < layered.size(); ++i) {
      if (layered[i] != normalized[s][i]) (*sets[s].outputs)[i] = frame.ToInput(layered[i]);
    }
    if (s == 0) {
      layered_only->assign(layered.size(), 0);
      for (size_t i = 0; i < layered.size(); ++i) {
        (*layered_only)[i] = layered[i] != separated[0][i] && !(*split)[i];
      }
    }
  }
  if (read_layers) clock->Lap("layers");
  return moved;
}

}  // namespace

const char* SolverName(Solver solver) {
  return solver == Solver::kAlternating ? "alternating" : "ceres";
}

bool ParseSolver(const std::string& name, Solver* solver) {
  constexpr Solver kSolvers[] = {Solver::kAlternating, Solver::kCeres};
  return ParseByName(name, kSolvers, SolverName, solver);
}

Initialization DenoiseOptions::EffectiveInitialization() const {
  if (initialization) return *initialization;
  return solver == Solver::kCeres ? Initialization::kPlaneFit : alternating_start;
}

NeighborhoodSizeOptions DenoiseOptions::ProbeOptions() const {
  NeighborhoodSizeOptions probe = neighborhood;
  probe.split_sheets = problem.split_sheets;
  return probe;
}

bool DenoiseOptions::IsValid(std::string* error) const {
  if (choose_k && !neighborhood.IsValid(error)) return false;
  if (!choose_k && !problem.IsValid(error)) return false;
  if (!settings.IsValid(error) || !weights.IsValid(error) || !minimizer.IsValid(error) ||
      !final_step.IsValid(error) || !far_points.IsValid(error)) {
    return false;
  }
  if (solver == Solver::kCeres) {
    if (!joint.IsValid(error)) return false;
    if (EffectiveInitialization() == Initialization::kZero) {
      *error = "the ceres solver cannot start from initialization zero (h_i = 0 is off the "
               "unit sphere); use plane_fit";
      return false;
    }
  }
  return true;
}

DenoiseState StartDenoising(const energy::PointList& points, const DenoiseOptions& options,
                            const energy::PointList* normals) {
  const Clock::time_point start = Clock::now();
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument(error);
  if (normals && normals->size() != points.size()) {
    throw std::invalid_argument("got " + std::to_string(normals->size()) + " normals for " +
                                std::to_string(points.size()) + " points");
  }
  DenoiseState state;
  StageClock clock(&state.stage_times);
  state.order = energy::MortonOrder(points);
  const int threads = options.settings.num_threads;
  const energy::PointList ordered_points = ToProblemOrder(points, state.order);
  energy::ProblemOptions problem_options = options.problem;
  energy::PointList solved_points = ordered_points;
  if (options.choose_k) {
    Thinning thinning = ChooseThinning(ordered_points, options.ProbeOptions(), threads);
    state.neighborhood = thinning.size;
    problem_options.k = state.neighborhood.k;
    // Thin regions grow wherever found where the noise is as wide as the spacing
    // (energy/sheet_split.h).
    if (state.neighborhood.read_sigma >= state.neighborhood.spacing) {
      problem_options.thin_region_growth = energy::ThinRegionGrowth::kEverywhere;
    }
    // Where few of the probe's regions nearly split, judging the splits on 2k + 1 points
    // rather than kSheetSplitPoints changes no cell of the benchmark's meshes and costs a
    // search of 2k + 1 (docs/performance.md); thin-walled parts need it.
    if (state.neighborhood.thin_candidate_fraction < kThinCloudShare) {
      problem_options.split_neighborhood = energy::SplitNeighborhood::kSplitPoints;
    }
    if (!thinning.rows.empty()) SplitOffUnsolved(thinning.rows, ordered_points, &state,
                                                 &solved_points);
  }
  clock.Lap("order and probe");
  CheckFitsInMemory(static_cast<int>(solved_points.size()), problem_options.k);
  // The problem's points are those the chosen probe searched (the whole cloud, or the
  // subsample in the same order): its search is reused.
  state.problem = energy::BuildProblem(solved_points, problem_options, threads,
                                       state.neighborhood.split_search.get());
  state.neighborhood.split_search.reset();
  state.neighborhood.k = state.problem.k();
  state.setup_seconds = SecondsSince(start);
  clock.Lap("graph");
  energy::PointList ordered_normals;
  if (normals) ordered_normals = ToProblemOrder(*normals, state.order);
  state.variables = InitialState(state.problem, options.settings.energy,
                                 options.EffectiveInitialization(), threads,
                                 options.initialization_seed,
                                 normals ? &ordered_normals : nullptr);
  clock.Lap("initial state");
  return state;
}

SolverSummary MinimizeFromState(const DenoiseOptions& options, DenoiseState* state,
                                const IterationCallback& callback) {
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument(error);
  StageClock clock(&state->stage_times);
  SolverSettings settings = options.settings;
  energy::DataScaledWeights weights = options.weights;
  weights.smoothing_balance *= state->neighborhood.smoothing_scale;
  settings.energy =
      energy::ScaleWeightsToData(state->problem, options.settings.energy, weights,
                                 options.settings.num_threads);
  SolverSummary summary;
  if (options.solver == Solver::kCeres) {
    if (settings.mu_l_noise_sigmas > 0.0) {  // the joint solve starts from fitted planes
      settings.energy.mu_l =
          NoiseScaledMuL(FittingNoiseSigma(state->problem, state->variables),
                         settings.mu_l_noise_sigmas);
    }
    summary = CeresJointSolver::Minimize(state->problem, settings, options.joint,
                                         &state->variables, callback);
    summary.mu_l = settings.energy.mu_l;
    summary.eta = settings.energy.eta;
    summary.lambda = settings.energy.lambda;
  } else {
    summary = AlternatingMinimizer::Minimize(state->problem, settings, options.minimizer,
                                             &state->variables, callback, &state->progress);
  }
  if (!summary.IsSolutionUsable()) {
    throw std::runtime_error("minimization failed: " + summary.message);
  }
  clock.Lap("solve");
  return summary;
}

DenoiseResult FinishDenoising(const DenoiseState& state, const DenoiseOptions& options,
                              SolverSummary summary) {
  const energy::Problem& problem = state.problem;
  const std::vector<int>& order = state.order;
  DenoiseResult result;
  result.stage_times = state.stage_times;
  StageClock clock(&result.stage_times);
  result.summary = std::move(summary);
  result.setup_seconds = state.setup_seconds;
  result.neighborhood = state.neighborhood;
  result.neighborhood.k = problem.k();  // also for a resumed state, which keeps no estimates
  result.solved_points = problem.num_points();
  result.subsampled = !state.left_out.empty();
  result.pass_summaries = {{static_cast<int>(state.order.size() + state.left_out.size()),
                            problem.num_points(), problem.k(), result.summary.num_iterations,
                            result.summary.termination}};
  const std::vector<LocalSurface> surfaces =
      options.final_step.projection == Projection::kSphere
          ? FitLocalSpheres(problem, state.variables, options.settings.num_threads)
          : TangentPlaneSurfaces(state.variables);
  // One weighting scale for the solved points and for those a subsample run extends to.
  const double agreement_scale = BlendAgreementScale(problem, surfaces);
  ProjectOntoBlendedSurfaces(problem, surfaces, options.final_step.blended_surfaces,
                             agreement_scale, options.final_step.settled_blend,
                             options.settings.num_threads, &result.projected, &result.normals);
  result.indicators = ComputeIndicators(problem, state.variables, result.summary.mu_l,
                                         options.final_step, options.settings.num_threads);
  clock.Lap("projection");
  // Even spacing and the offset feedback move the output in the normalized frame; outliers
  // stay where they are.
  energy::PointList normalized;
  std::vector<uint8_t> movable;
  auto normalize_output = [&] {
    normalized.resize(result.projected.size());
    movable.resize(result.projected.size());
    for (size_t i = 0; i < normalized.size(); ++i) {
      normalized[i] = problem.frame.ToNormalized(result.projected[i]);
      movable[i] = !result.indicators.is_outlier[i];
    }
  };
  // Takes the outputs a step moved (`moved`, normalized frame, in the order of `normalized`).
  auto take_moved = [&](const energy::PointList& moved) {
    for (size_t i = 0; i < normalized.size(); ++i) {
      if (moved[i] != normalized[i]) result.projected[i] = problem.frame.ToInput(moved[i]);
    }
  };
  // Spreads the outputs flagged in `spreading` evenly over the surface (even_spacing.h), each
  // following its own fitted surface: it keeps the blend's offset from it. `kernel`: as
  // SpreadEvenly takes it.
  auto spread_evenly = [&](const std::vector<uint8_t>& spreading, double* kernel) {
    energy::PointList spread =
        SpreadEvenly(normalized, result.normals, spreading,
                     options.final_step.even_spacing_rounds, options.settings.num_threads,
                     kernel);
    HoldWithinInputs(normalized, problem.points, problem.graph, spreading,
                     state.neighborhood.noise_sigma, options.settings.num_threads, &spread);
    for (size_t i = 0; i < normalized.size(); ++i) {
      Eigen::Vector3d from, to, normal;
      if (!spreading[i] || !surfaces[i].Project(normalized[i], &from, &normal) ||
          !surfaces[i].Project(spread[i], &to, &normal)) {
        continue;
      }
      result.projected[i] = problem.frame.ToInput(normalized[i] + (to - from));
    }
  };
  double first_kernel = 0.0;  // the first rounds' kernel
  if (options.final_step.even_spacing_rounds > 0) {
    normalize_output();
    spread_evenly(movable, &first_kernel);
    clock.Lap("even spacing");
  }
  const NeighborhoodSize& estimates = state.neighborhood;
  const bool feed_back = options.final_step.offset_feedback && estimates.spacing > 0.0 &&
                         estimates.read_sigma <= kCalibratedReadRatio * estimates.spacing;
  energy::PointList fed_back;
  if (feed_back) {
    normalize_output();
    fed_back = FeedBackMeanOffsets(problem.points, normalized, result.normals, movable,
                                   options.settings.num_threads);
    for (size_t i = 0; i < normalized.size(); ++i) {
      result.projected[i] = problem.frame.ToInput(fed_back[i]);
    }
    clock.Lap("offset feedback");
  }
  energy::PointList extended_points, extended_normals;
  PointIndicators extended;
  if (!state.left_out.empty()) {
    ExtendToPoints(problem, state.variables, surfaces, agreement_scale, result.indicators,
                   result.summary.mu_l, options.final_step, state.left_out_points,
                   options.settings.num_threads, &extended_points, &extended_normals, &extended);
    if (feed_back) {
      energy::PointList points(extended_points.size());
      std::vector<uint8_t> extended_movable(points.size());
      for (size_t q = 0; q < points.size(); ++q) {
        points[q] = problem.frame.ToNormalized(extended_points[q]);
        extended_movable[q] = !extended.is_outlier[q];
      }
      points = CarryFeedback(normalized, fed_back, result.normals, movable, points,
                             extended_normals, extended_movable, options.settings.num_threads);
      for (size_t q = 0; q < points.size(); ++q) {
        extended_points[q] = problem.frame.ToInput(points[q]);
      }
    }
    clock.Lap("subsample extension");
  }
  // Merged sides of a thin part, told apart (merged_sides.h): the solved points and those of
  // a subsample run's extension, with one count of merged regions. A resumed run keeps no
  // estimates and skips it, as it skips the feedback.
  if (options.final_step.separate_merged_sides && estimates.noise_sigma > 0.0) {
    // The points left between two output layers, where the probe reads the noise wider than
    // the spacing, and the layers' heights from their inputs, there and where the probe's
    // regions split as often as on thin parts (between_layers.h).
    const bool move_between = estimates.spacing > 0.0 &&
                              estimates.read_sigma > kMoveBetweenReadRatio * estimates.spacing;
    const bool read_layers =
        move_between || estimates.two_sheet_fraction >= kThinCloudShare;
    std::vector<SidesInput> sets = {
        {problem.points, result.normals, result.indicators.is_outlier, &result.projected}};
    energy::PointList extended_inputs(state.left_out_points.size());  // normalized frame
    for (size_t q = 0; q < extended_inputs.size(); ++q) {
      extended_inputs[q] = problem.frame.ToNormalized(state.left_out_points[q]);
    }
    if (!state.left_out.empty()) {
      sets.push_back({extended_inputs, extended_normals, extended.is_outlier, &extended_points});
    }
    std::vector<uint8_t> split, layered_only;
    result.num_separated = SeparateSides(problem.frame, sets, read_layers, move_between,
                                         options.settings.num_threads, &clock, &split,
                                         &layered_only);
    // Each side of a split region holds about half of the points spread over the merged
    // layer, drawn at random: spread again, the split points only, with a kernel measured on
    // them (docs/method.md, "Even spacing", "After the sides are told apart"). Then the
    // points the layers' step moved, where it moved most of the points (the layers of a thin
    // part), with the first rounds' kernel: measured on points spread already, a kernel is
    // wider and its steps overshoot ("The layers' points spread again").
    const auto layered_count = std::count(layered_only.begin(), layered_only.end(), 1);
    if (layered_count < kMinLayeredShareToSpread * static_cast<double>(layered_only.size())) {
      layered_only.assign(layered_only.size(), 0);
    }
    if (options.final_step.even_spacing_rounds > 0) {
      for (const std::vector<uint8_t>* moved : {&split, &layered_only}) {
        if (std::find(moved->begin(), moved->end(), 1) == moved->end()) continue;
        normalize_output();  // every point not an outlier movable again
        for (size_t i = 0; i < movable.size(); ++i) movable[i] = movable[i] && (*moved)[i];
        double measured = 0.0;
        spread_evenly(movable, moved == &split ? &measured : &first_kernel);
        clock.Lap("even spacing again");
      }
    }
  }
  // The heights smoothed (height_smoothing.h), within two noise deviations; a resumed run
  // keeps no noise estimate and skips it.
  if (options.final_step.height_smoothing_pairs > 0 && estimates.read_sigma > 0.0) {
    normalize_output();
    const energy::PointList smoothed =
        SmoothHeights(normalized, result.normals, movable,
                      kHeightBandDeviations * estimates.read_sigma,
                      options.final_step.height_smoothing_pairs, options.settings.num_threads);
    take_moved(smoothed);
    clock.Lap("height smoothing");
  }
  // Each height refitted at the widest scale its neighbours agree on (adaptive_heights.h),
  // where the probe reads the noise narrower than the spacing.
  if (options.final_step.adaptive_heights && estimates.spacing > 0.0 &&
      estimates.read_sigma <= kMoveBetweenReadRatio * estimates.spacing) {
    normalize_output();
    const energy::PointList refitted = RefitHeightsAtAdaptiveScale(
        normalized, result.normals, movable, options.settings.num_threads);
    take_moved(refitted);
    clock.Lap("adaptive heights");
  }
  if (options.final_step.snap_features) {
    result.snapping = SnapFeaturePoints(problem, state.variables, result.indicators.is_feature,
                                        options.final_step.snapping, &result.projected);
    clock.Lap("feature snapping");
  }
  const std::vector<int>& left_out = state.left_out;
  result.projected = ToInputOrder(result.projected, order, extended_points, left_out);
  result.normals = ToInputOrder(result.normals, order, extended_normals, left_out);
  PointIndicators& indicators = result.indicators;
  indicators.outlier_score =
      ToInputOrder(indicators.outlier_score, order, extended.outlier_score, left_out);
  indicators.feature_score =
      ToInputOrder(indicators.feature_score, order, extended.feature_score, left_out);
  indicators.is_outlier = ToInputOrder(indicators.is_outlier, order, extended.is_outlier, left_out);
  indicators.is_feature = ToInputOrder(indicators.is_feature, order, extended.is_feature, left_out);
  const int n = static_cast<int>(result.projected.size());
  for (int i = 0; i < n; ++i) {
    result.num_outliers += result.indicators.is_outlier[i];
    result.num_features += result.indicators.is_feature[i];
  }
  bool remove = options.final_step.remove_outliers;
  if (remove && result.num_outliers > options.final_step.max_removed_fraction * n) {
    char note[256];
    std::snprintf(note, sizeof(note),
                  "outliers kept: %.1f%% of the points were flagged (more than "
                  "max_removed_fraction = %.0f%%), so mu_l = %.3g is below the noise level",
                  100.0 * result.num_outliers / n,
                  100.0 * options.final_step.max_removed_fraction, result.summary.mu_l);
    result.removal_note = note;
    remove = false;
  }
  result.kept.assign(n, 1);
  if (remove) {
    for (int i = 0; i < n; ++i) result.kept[i] = !result.indicators.is_outlier[i];
    result.num_removed = result.num_outliers;
  }
  return result;
}

namespace {

bool StoppedByCallback(const DenoiseResult& result) {
  return result.summary.termination == TerminationType::kUserAbort;
}

// The passes after `first` and the isolation test (DenoisePointSet).
DenoiseResult RerunWithoutOutliers(const energy::PointList& points, const DenoiseOptions& options,
                                   DenoiseResult first, const IterationCallback& callback,
                                   const energy::PointList* normals) {
  DenoiseResult result = std::move(first);
  // last_rows[r]: the input index of row r of the last pass.
  std::vector<int> last_rows(points.size());
  for (size_t i = 0; i < points.size(); ++i) last_rows[i] = static_cast<int>(i);
  int removed_by_last = result.num_removed;
  for (int pass = 2; pass <= options.final_step.outlier_passes; ++pass) {
    if (StoppedByCallback(result)) break;
    if (removed_by_last <= options.final_step.rerun_removed_fraction * last_rows.size()) break;
    std::vector<int> rows;
    energy::PointList kept_points, kept_normals;
    for (int i : last_rows) {
      if (!result.kept[i]) continue;
      rows.push_back(i);
      kept_points.push_back(points[i]);
      if (normals) kept_normals.push_back((*normals)[i]);
    }
    const int fewest = (options.choose_k ? options.neighborhood.min_k : options.problem.k) + 1;
    if (static_cast<int>(rows.size()) <= fewest) break;
    DenoiseState state = StartDenoising(kept_points, options, normals ? &kept_normals : nullptr);
    SolverSummary summary = MinimizeFromState(options, &state, callback);
    const DenoiseResult next = FinishDenoising(state, options, std::move(summary));
    for (size_t r = 0; r < rows.size(); ++r) {
      const int i = rows[r];
      result.projected[i] = next.projected[r];
      result.normals[i] = next.normals[r];
      result.indicators.outlier_score[i] = next.indicators.outlier_score[r];
      result.indicators.feature_score[i] = next.indicators.feature_score[r];
      result.indicators.is_outlier[i] = next.indicators.is_outlier[r];
      result.indicators.is_feature[i] = next.indicators.is_feature[r];
      result.kept[i] = next.kept[r];
    }
    result.num_removed += next.num_removed;
    result.summary = next.summary;
    result.snapping = next.snapping;
    result.num_separated = next.num_separated;
    result.removal_note = next.removal_note;
    result.passes = pass;
    result.neighborhood = next.neighborhood;
    result.solved_points = next.solved_points;
    result.subsampled = next.subsampled;
    result.pass_summaries.push_back(next.pass_summaries.front());
    result.stage_times.Add(next.stage_times);
    removed_by_last = next.num_removed;
    last_rows = std::move(rows);
  }
  if (options.final_step.remove_outliers && result.removal_note.empty() &&
      !StoppedByCallback(result)) {
    StageClock clock(&result.stage_times);
    const std::vector<uint8_t> isolated = FlagIsolatedPoints(
        points, result.kept, options.final_step.isolation, options.settings.num_threads);
    for (size_t i = 0; i < points.size(); ++i) {
      if (!isolated[i]) continue;
      result.indicators.is_outlier[i] = 1;
      result.kept[i] = 0;
      ++result.num_isolated;
    }
    result.num_removed += result.num_isolated;
    clock.Lap("isolation test");
  }
  result.num_outliers = 0;
  result.num_features = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    result.num_outliers += result.indicators.is_outlier[i];
    result.num_features += result.indicators.is_feature[i];
  }
  return result;
}

}  // namespace

namespace {

// Every stage on `points`, which hold no far points.
DenoiseResult DenoiseNearPoints(const energy::PointList& points, const DenoiseOptions& options,
                                const DenoiseHooks& hooks, const energy::PointList* normals) {
  DenoiseState state = StartDenoising(points, options, normals);
  if (hooks.on_started) hooks.on_started(state);
  SolverSummary summary = MinimizeFromState(options, &state, hooks.progress);
  if (hooks.on_minimized) hooks.on_minimized(state);
  return RerunWithoutOutliers(points, options,
                              FinishDenoising(state, options, std::move(summary)),
                              hooks.progress, normals);
}

// The result on the solved points (`rows` of the input, increasing), extended to all input
// points: far points stay where they are, flagged as outliers with score 1; a repeated
// point takes the result of its first occurrence first[i], a near repeat that result moved
// by its offset from first[i] within the tangent plane there.
DenoiseResult ToAllInputPoints(DenoiseResult solved, const std::vector<int>& rows,
                               const std::vector<uint8_t>& far, const std::vector<int>& first,
                               const energy::PointList& points, bool remove_outliers) {
  const size_t n = points.size();
  DenoiseResult result = std::move(solved);
  std::vector<int> row_of(n, -1);
  for (size_t r = 0; r < rows.size(); ++r) row_of[rows[r]] = static_cast<int>(r);
  energy::PointList projected = points, normals(n, energy::Point3::Zero());
  PointIndicators indicators;
  indicators.outlier_score.assign(n, 1.0);
  indicators.feature_score.assign(n, 0.0);
  indicators.is_outlier.assign(n, 1);
  indicators.is_feature.assign(n, 0);
  std::vector<uint8_t> kept(n, remove_outliers ? 0 : 1);
  result.num_far = 0;
  for (size_t i = 0; i < n; ++i) {
    if (far[i]) {
      ++result.num_far;
      continue;
    }
    const int r = row_of[first[i]];
    projected[i] = result.projected[r];
    normals[i] = result.normals[r];
    if (points[i] != points[first[i]]) {  // a near repeat
      const energy::Point3 offset = points[i] - points[first[i]];
      projected[i] += offset - offset.dot(normals[i]) * normals[i];
    }
    indicators.outlier_score[i] = result.indicators.outlier_score[r];
    indicators.feature_score[i] = result.indicators.feature_score[r];
    indicators.is_outlier[i] = result.indicators.is_outlier[r];
    indicators.is_feature[i] = result.indicators.is_feature[r];
    kept[i] = result.kept[r];
  }
  result.num_outliers = 0;
  result.num_features = 0;
  result.num_removed = 0;
  for (size_t i = 0; i < n; ++i) {
    result.num_outliers += indicators.is_outlier[i];
    result.num_features += indicators.is_feature[i];
    result.num_removed += !kept[i];
  }
  result.projected = std::move(projected);
  result.normals = std::move(normals);
  result.indicators = std::move(indicators);
  result.kept = std::move(kept);
  return result;
}

// mark_outliers: every removed point back in the result at `input_points[i]`, flagged.
void MarkRemovedPoints(const energy::PointList& input_points, DenoiseResult* result) {
  for (size_t i = 0; i < result->kept.size(); ++i) {
    if (result->kept[i]) continue;
    result->kept[i] = 1;
    result->projected[i] = input_points[i];
    result->normals[i].setZero();
  }
  result->num_removed = 0;
}

// The input coordinates of a state's points, in input order: the problem's points taken
// back out of the normalized frame, and the points left out of a subsample as they were.
energy::PointList InputPointsOf(const DenoiseState& state) {
  energy::PointList points(state.order.size() + state.left_out.size());
  for (size_t r = 0; r < state.order.size(); ++r) {
    points[state.order[r]] = state.problem.frame.ToInput(state.problem.points[r]);
  }
  for (size_t e = 0; e < state.left_out.size(); ++e) {
    points[state.left_out[e]] = state.left_out_points[e];
  }
  return points;
}

}  // namespace

DenoiseResult DenoisePointSet(const energy::PointList& points, const DenoiseOptions& options,
                              const DenoiseHooks& hooks, const energy::PointList* normals) {
  const Clock::time_point start = Clock::now();
  StageTimes before_passes;
  StageClock clock(&before_passes);
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument(error);
  const std::vector<uint8_t> far = FlagFarPoints(points, options.far_points);
  std::vector<int> first(points.size());
  if (options.merge_duplicates) {
    first = FirstOccurrences(points);
  } else {
    std::iota(first.begin(), first.end(), 0);
  }
  std::vector<int> rows;  // the points solved: neither far nor a repeat of an earlier one
  size_t repeats = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const bool repeat = first[i] != static_cast<int>(i);
    repeats += repeat;
    if (!far[i] && !repeat) rows.push_back(static_cast<int>(i));
  }
  size_t near_repeats = 0;
  if (options.merge_duplicates) {
    energy::PointList distinct(rows.size());
    for (size_t r = 0; r < rows.size(); ++r) distinct[r] = points[rows[r]];
    const std::vector<int> representative =
        NearRepeatRepresentatives(distinct, options.settings.num_threads);
    std::vector<int> kept_rows;
    for (size_t r = 0; r < rows.size(); ++r) {
      if (representative[r] == static_cast<int>(r)) {
        kept_rows.push_back(rows[r]);
      } else {
        first[rows[r]] = rows[representative[r]];
        ++near_repeats;
      }
    }
    rows = std::move(kept_rows);
    repeats += near_repeats;
    // An exact repeat of a near repeat follows it to its representative.
    for (int& f : first) f = first[f];
  }
  const size_t fewest = (options.choose_k ? options.neighborhood.min_k : options.problem.k) + 1;
  if (repeats > 0 && rows.size() < fewest) {
    throw std::invalid_argument(
        "only " + std::to_string(points.size() - repeats) +
        (points.size() - repeats == 1 ? " distinct point among " : " distinct points among ") +
        std::to_string(points.size()) + " (the others repeat them): need at least " +
        std::to_string(fewest) + (options.choose_k ? " to choose k from the data" : "") +
        " (give a smaller --k)");
  }
  clock.Lap("far points and repeats");
  DenoiseOptions for_cloud = options;
  for_cloud.final_step = options.final_step.ForCloudOf(rows.size());
  DenoiseResult result;
  if (rows.size() == points.size()) {
    result = DenoiseNearPoints(points, for_cloud, hooks, normals);
  } else {
    energy::PointList solved_points, solved_normals;
    for (int i : rows) {
      solved_points.push_back(points[i]);
      if (normals) solved_normals.push_back((*normals)[i]);
    }
    result = ToAllInputPoints(
        DenoiseNearPoints(solved_points, for_cloud, hooks, normals ? &solved_normals : nullptr),
        rows, far, first, points, options.final_step.remove_outliers);
  }
  result.num_duplicates = static_cast<int>(repeats - near_repeats);
  result.num_near_repeats = static_cast<int>(near_repeats);
  if (options.mark_outliers) MarkRemovedPoints(points, &result);
  before_passes.Add(result.stage_times);
  result.stage_times = std::move(before_passes);
  result.total_seconds = SecondsSince(start);
  return result;
}

DenoiseResult ContinueDenoising(DenoiseState state, const DenoiseOptions& options,
                                const DenoiseHooks& hooks) {
  const Clock::time_point start = Clock::now();
  SolverSummary summary = MinimizeFromState(options, &state, hooks.progress);
  if (hooks.on_minimized) hooks.on_minimized(state);
  DenoiseOptions for_cloud = options;  // the cloud the first pass solved, as DenoisePointSet
  for_cloud.final_step =
      options.final_step.ForCloudOf(state.order.size() + state.left_out.size());
  DenoiseResult result = FinishDenoising(state, for_cloud, std::move(summary));
  if (options.mark_outliers) MarkRemovedPoints(InputPointsOf(state), &result);
  result.total_seconds = SecondsSince(start);
  return result;
}

}  // namespace lpd::solvers
