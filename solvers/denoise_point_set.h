// lpd: the whole method in one call: points in, denoised points and indicators out.
//
// Builds the problem (normalization, N, M, alpha, beta), minimizes Eq. (5) with Alg. 1 (or
// with the Ceres joint solve, the validation solver), then runs the final denoising of
// Sec. 3.4. Inputs are never modified. DenoisePointSet sequences the stages; they are also
// callable one by one, for tests and ablations that look between them.
#ifndef LPD_SOLVERS_DENOISE_POINT_SET_H_
#define LPD_SOLVERS_DENOISE_POINT_SET_H_

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "energy/data_scaled_weights.h"
#include "energy/point3.h"
#include "energy/problem.h"
#include "solvers/alternating_minimizer.h"
#include "solvers/ceres_joint_solver.h"
#include "solvers/far_points.h"
#include "solvers/final_denoising.h"
#include "solvers/initial_state.h"
#include "solvers/neighborhood_size.h"
#include "solvers/solver_settings.h"
#include "solvers/solver_summary.h"
#include "solvers/stage_times.h"

namespace lpd::solvers {

enum class Solver {
  kAlternating,  // Alg. 1, the paper's method
  kCeres,        // the joint solve (the validation solver)
};
const char* SolverName(Solver solver);  // "alternating", "ceres"
bool ParseSolver(const std::string& name, Solver* solver);

struct DenoiseOptions {
  energy::ProblemOptions problem;            // k and the duplicate-point guard
  // When set, problem.k is replaced by the k chosen from the data (neighborhood_size.h).
  bool choose_k = true;
  NeighborhoodSizeOptions neighborhood;
  // The energy's weights, the noise-scaled mu_l and the thread count of every stage, for
  // whichever solver runs.
  SolverSettings settings;
  // Alg. 1's schedule, stopping rule, GNC and T solver.
  AlternatingMinimizer::Options minimizer;
  // eta and lambda from the data (fit and smoothing balance); replaces settings.energy's
  // eta and lambda for both solvers unless a balance is 0.
  energy::DataScaledWeights weights;
  Solver solver = Solver::kAlternating;
  CeresJointSolver::Options joint;           // used when solver == kCeres
  // The start of the minimization; unset means `alternating_start` for Alg. 1 and kPlaneFit
  // for the joint solve (which needs every h_i on the unit sphere).
  std::optional<Initialization> initialization;
  // Alg. 1's start where `initialization` is unset: kPlaneFit, the PCA planes with T = H and
  // S oriented by them, so that the first T solve does not average planes of opposite
  // orientation (docs/method.md, "The start"); the paper preset's kZero is Alg. 1 as
  // published (H = T = 0, S = 1).
  Initialization alternating_start = Initialization::kPlaneFit;
  int initialization_seed = 1;               // of initialization random
  FinalDenoisingOptions final_step;          // indicators and outlier removal
  // Stray points far from the whole cloud, set aside before the first stage (DenoisePointSet).
  FarPointOptions far_points;
  // Points given more than once are solved once and each copy takes the result
  // (duplicate_points.h), as are near repeats where they are common (near_repeats.h; each
  // keeps its offset along the surface); paper: false.
  bool merge_duplicates = true;
  // Keep every point in the result: those the passes removed get kept = 1 back, at their
  // input position with a zero normal, still flagged (is_outlier) with their score.
  bool mark_outliers = false;

  Initialization EffectiveInitialization() const;
  // `neighborhood` with the probe told whether sheets are split (problem.split_sheets).
  NeighborhoodSizeOptions ProbeOptions() const;

  bool IsValid(std::string* error) const;
};

// One denoising pass: its problem and how its minimization ended.
struct PassSummary {
  int points = 0;       // in the pass's input (before any subsample)
  int solved_points = 0;
  int k = 0;
  int iterations = 0;
  TerminationType termination = TerminationType::kFailure;
};

struct DenoiseResult {
  // One entry per input point, in input order and frame.
  energy::PointList projected;       // p_i projected onto t_i
  energy::PointList normals;         // unit normal of t_i (zero if undefined)
  PointIndicators indicators;
  // True for the points that are in the output (not removed as outliers; all of them with
  // mark_outliers).
  std::vector<uint8_t> kept;
  int num_outliers = 0;              // flagged by the indicator
  int num_removed = 0;               // actually removed
  int num_isolated = 0;              // of those, found by the isolation test
  int num_far = 0;                   // of those, far from the whole cloud (far_points.h)
  int num_duplicates = 0;            // input points that repeat an earlier one (merged)
  int num_near_repeats = 0;          // input points within a tenth of a spacing of one (merged)
  int num_separated = 0;             // output points moved to their side (merged_sides.h)
  int num_features = 0;
  SnappingCounts snapping;           // with final_step.snap_features
  int passes = 1;                    // denoising passes run (RerunWithoutOutliers)
  std::vector<PassSummary> pass_summaries;  // one per pass, in order
  NeighborhoodSize neighborhood;     // k (and its estimates when chosen) of the last pass
  int solved_points = 0;             // points in the last pass's problem (thinning.h)
  bool subsampled = false;           // the last pass solved a subsample and extended it
  std::string removal_note;          // why flagged outliers were kept, if they were
  SolverSummary summary;
  double setup_seconds = 0.0;        // normalization and k-NN graph
  double total_seconds = 0.0;
  StageTimes stage_times;            // every pass's stages (stage_times.h)
};

// A denoising run between its stages: the problem with its points in Morton order (for
// memory locality), the optimizer's state, and the way back to input order.
struct DenoiseState {
  std::vector<int> order;  // problem point r is input point order[r]
  energy::Problem problem;
  energy::Variables variables;
  MinimizerProgress progress;
  // The noise and spacing estimates behind k when it was chosen from the data (else k only).
  NeighborhoodSize neighborhood;
  double setup_seconds = 0.0;  // normalization and k-NN graph
  StageTimes stage_times;      // the stages run so far; not saved with the state
  // When the problem holds a subsample (subsample_extension.h), the input points left out of
  // it: their input indices and coordinates. FinishDenoising extends the result to them.
  std::vector<int> left_out;
  energy::PointList left_out_points;
};

// Stage 1: normalization, N and M, and the initial state. `normals` (in input order) are
// needed by initialization input_normals only. Throws std::invalid_argument with a one-line
// reason on invalid options or input.
DenoiseState StartDenoising(const energy::PointList& points, const DenoiseOptions& options,
                            const energy::PointList* normals = nullptr);

// Stage 2: minimizes Eq. (5) from `state`, continuing where its progress stands (Alg. 1) or
// from its variables (the joint solve). Throws std::runtime_error if the solver failed.
SolverSummary MinimizeFromState(const DenoiseOptions& options, DenoiseState* state,
                                const IterationCallback& callback = nullptr);

// Stage 3: the final denoising of Sec. 3.4, in input order and frame.
DenoiseResult FinishDenoising(const DenoiseState& state, const DenoiseOptions& options,
                              SolverSummary summary);

// What a caller of DenoisePointSet sees of the run, or adds to it, between the stages.
struct DenoiseHooks {
  // After every iteration of every pass; returning false stops the run (the minimization
  // ends with USER_ABORT, no further pass starts, no isolation test runs).
  IterationCallback progress;
  // After the first pass's StartDenoising (e.g. to measure the problem) and after its
  // minimization (e.g. to save the state for a warm restart). An exception thrown here ends
  // the run.
  std::function<void(const DenoiseState&)> on_started;
  std::function<void(const DenoiseState&)> on_minimized;
};

// The pipeline, sequenced here only: the far points set aside (options.far_points; they are
// flagged as outliers with score 1 and keep their input position) and repeated points merged
// (options.merge_duplicates; each copy takes its first occurrence's result, a near repeat
// that result moved along the tangent plane by its offset from it, and the counts
// of the result are over all input points but num_isolated, over the points solved), then
// StartDenoising, MinimizeFromState, FinishDenoising,
// then further passes without the outliers (options.final_step.outlier_passes: while the
// last pass removed more than rerun_removed_fraction of its points, the points it kept are
// denoised again from their input coordinates, and their results replace the earlier ones;
// removed points keep the values of the pass that removed them), then the isolation test on
// the kept input points (options.final_step.isolation). `normals` (input order) are needed by
// initialization input_normals only. Throws std::invalid_argument with a one-line reason on
// invalid options or input, std::runtime_error if the solver failed.
DenoiseResult DenoisePointSet(const energy::PointList& points, const DenoiseOptions& options,
                              const DenoiseHooks& hooks = {},
                              const energy::PointList* normals = nullptr);

// Continues a saved run (a warm restart, Sec. 4.1): MinimizeFromState from `state`, then
// FinishDenoising. No further pass and no isolation test: they need the input points, which
// a state does not keep.
DenoiseResult ContinueDenoising(DenoiseState state, const DenoiseOptions& options,
                                const DenoiseHooks& hooks = {});

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_DENOISE_POINT_SET_H_
