#include "solvers/alternating_minimizer.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "energy/energy.h"
#include "energy/fitting_term.h"
#include "energy/smoothness_term.h"
#include "energy/wall_clock.h"
#include "solvers/local_plane_fit.h"
#include "solvers/residual_statistics.h"

namespace lpd::solvers {

bool AlternatingMinimizer::Options::IsValid(std::string* error) const {
  if (!linear_solver.IsValid(error)) return false;
  std::ostringstream out;
  if (max_iterations < 1) {
    out << "max_iters must be >= 1, got " << max_iterations;
  } else if (inner_iterations < 1) {
    out << "inner_iters must be >= 1, got " << inner_iterations;
  } else if (!(energy_tolerance >= 0.0) || !std::isfinite(energy_tolerance)) {
    out << "energy_tolerance must be finite and >= 0, got " << energy_tolerance;
  } else if (!(progress_tolerance >= 0.0) || !std::isfinite(progress_tolerance)) {
    out << "progress_tolerance must be finite and >= 0, got " << progress_tolerance;
  } else if (!(motion_tolerance >= 0.0) || !std::isfinite(motion_tolerance)) {
    out << "motion_tolerance must be finite and >= 0, got " << motion_tolerance;
  } else if (energy_window < 1) {
    out << "energy_window must be >= 1, got " << energy_window;
  } else if (!gnc.IsValid(error)) {
    return false;
  } else {
    return true;
  }
  *error = out.str();
  return false;
}

namespace {

// One call of Minimize: Alg. 1's outer loop over the state it continues (`progress`), with
// block timing and tracing, graduated non-convexity and the stopping rule kept apart.
class AlternatingRun {
 public:
  AlternatingRun(const energy::Problem& problem, const SolverSettings& settings,
                 const AlternatingMinimizer::Options& options, energy::Variables* v,
                 MinimizerProgress* state)
      : problem_(problem),
        settings_(settings),
        options_(options),
        v_(v),
        state_(*state),
        threads_(settings.num_threads),
        parameters_(settings.energy),
        selectivities_(options.gnc, &state->gnc),
        smoother_(problem, threads_) {
    // The energy of Eq. (5) at the target selectivities; mu_l may still be replaced by the
    // scale-aware value at the first local step.
    if (!std::isnan(state_.mu_l)) parameters_.mu_l = state_.mu_l;
    if (!options.optimize_orientations) v->s.setOnes();
  }

  SolverSummary Run(const IterationCallback& callback) {
    const Clock::time_point initial_start = Clock::now();
    summary_.initial_energy = energy::EvaluateEnergy(problem_, parameters_, *v_, threads_);
    traced_seconds_ = SecondsSince(initial_start);
    summary_.termination = TerminationType::kNoConvergence;
    summary_.message = "reached max_iters";
    const int last_iteration = state_.iterations + options_.max_iterations;
    for (int iteration = state_.iterations + 1; iteration <= last_iteration; ++iteration) {
      const IterationRecord record = RunIteration(iteration);
      const bool at_targets = selectivities_.EndIteration(parameters_.mu_l, parameters_.mu_m);
      if (!std::isfinite(record.energy.total())) {
        Stop(TerminationType::kFailure, "the energy became non-finite at iteration " +
                                            std::to_string(iteration));
        break;
      }
      if (callback && !callback(record)) {
        Stop(TerminationType::kUserAbort, "stopped by the callback");
        break;
      }
      if (at_targets && Converged(record)) break;
    }
    if (summary_.termination == TerminationType::kNoConvergence) DescribeNoConvergence();
    summary_.mu_l = parameters_.mu_l;
    summary_.eta = parameters_.eta;
    summary_.lambda = parameters_.lambda;
    summary_.total_seconds = SecondsSince(run_start_);
    return summary_;
  }

 private:
  // One outer iteration of Alg. 1: the local step (lines 9-10), then inner_iterations passes
  // of the global step (lines 12-18).
  IterationRecord RunIteration(int iteration) {
    const Clock::time_point iteration_start = Clock::now();
    const energy::PlaneField previous_t = v_->t;
    IterationRecord record;
    record.iteration = iteration;
    LocalStep(&record);
    for (int inner = 1; inner <= options_.inner_iterations; ++inner) GlobalPass(inner, &record);
    record.energy = options_.trace_blocks
                        ? summary_.steps.back().energy
                        : energy::EvaluateEnergy(problem_, parameters_, *v_, threads_);
    if (iteration > 1) {
      record.point_motion = RmsProjectedPointChange(problem_, previous_t, v_->t, threads_);
    }
    record.seconds = SecondsSince(iteration_start);
    record.elapsed_seconds = SecondsSince(run_start_) - traced_seconds_;
    summary_.iterations.push_back(record);
    summary_.num_iterations = iteration;
    summary_.final_energy = record.energy;
    state_.iterations = iteration;
    return record;
  }

  // H (Eq. 10), then L (Eq. 6) at the scheduled mu_l. The first local step reads the noise
  // from its fit and fixes the target mu_l (from the noise when mu_l_noise_sigmas > 0).
  void LocalStep(IterationRecord* record) {
    record->local_seconds += RunBlock("H", record->iteration, 0, [&] {
      UpdateLocalPlanes(problem_, parameters_, threads_, v_);
      return -1;
    }).seconds;
    if (std::isnan(state_.noise_sigma)) state_.noise_sigma = FittingNoiseSigma(problem_, *v_);
    if (std::isnan(state_.mu_l)) {
      if (settings_.mu_l_noise_sigmas > 0.0) {
        parameters_.mu_l = NoiseScaledMuL(state_.noise_sigma, settings_.mu_l_noise_sigmas);
      }
      state_.mu_l = parameters_.mu_l;
    }
    record->mu_l = selectivities_.FittingSelectivity(
        parameters_.mu_l, [&] { return MaxSquaredFittingResidual(problem_, *v_, threads_); });
    const energy::FittingTerm fitting(problem_, record->mu_l, threads_);
    record->local_seconds += RunBlock("L", record->iteration, 0, [&] {
      fitting.UpdateLineProcesses(v_);
      return -1;
    }).seconds;
  }

  // T (Eq. 9), M (Eq. 7) at the scheduled mu_m, and S (Eq. 8).
  void GlobalPass(int inner, IterationRecord* record) {
    const int iteration = record->iteration;
    const StepRecord t_step = RunBlock("T", iteration, inner, [&] {
      return smoother_.Update(parameters_, options_.linear_solver, threads_, v_).iterations;
    });
    record->global_seconds += t_step.seconds;
    record->cg_iterations += t_step.cg_iterations;
    record->mu_m = selectivities_.SmoothnessSelectivity(
        parameters_.mu_m, [&] { return MaxSquaredSmoothnessResidual(problem_, *v_, threads_); });
    const energy::SmoothnessTerm smoothness(problem_, parameters_.lambda, record->mu_m,
                                            threads_);
    record->global_seconds += RunBlock("M", iteration, inner, [&] {
      smoothness.UpdateLineProcesses(v_);
      return -1;
    }).seconds;
    if (options_.optimize_orientations) {
      record->global_seconds += RunBlock("S", iteration, inner, [&] {
        smoothness.UpdateOrientations(v_);
        return -1;
      }).seconds;
    }
  }

  // Runs one block update, times it and, when tracing, records the energy after it.
  template <typename Update>
  StepRecord RunBlock(const char* block, int iteration, int inner, Update&& update) {
    const Clock::time_point start = Clock::now();
    StepRecord step;
    step.cg_iterations = update();
    step.seconds = SecondsSince(start);
    step.block = block;
    step.iteration = iteration;
    step.inner_iteration = inner;
    if (options_.trace_blocks) {
      const Clock::time_point trace_start = Clock::now();
      step.energy = energy::EvaluateEnergy(problem_, parameters_, *v_, threads_);
      traced_seconds_ += SecondsSince(trace_start);
    }
    summary_.steps.push_back(step);
    return step;
  }

  // The stopping rules over the iterations run at the target selectivities, w =
  // energy_window: |E_t - E_{t-w}| <= energy_tolerance |E_{t-w}|, or
  // E_{t-w} - E_t <= progress_tolerance (E_1 - E_t), or the last w iterations each moved
  // the outputs by at most motion_tolerance noise deviations.
  bool Converged(const IterationRecord& record) {
    const double total = record.energy.total();
    std::vector<double>& history = state_.energy_history;
    history.push_back(total);
    state_.motion_history.push_back(record.point_motion);
    const int w = options_.energy_window;
    if (static_cast<int>(history.size()) <= w) return false;
    const double before = history[history.size() - 1 - w];
    const double change = std::abs(total - before);
    std::ostringstream out;
    if (options_.energy_tolerance > 0.0 &&
        change <= options_.energy_tolerance * std::abs(before)) {
      out << "energy changed by less than " << 100.0 * options_.energy_tolerance << "% over "
          << w << " iterations";
    } else if (options_.progress_tolerance > 0.0 && total <= before &&
               before - total <= options_.progress_tolerance * (history.front() - total)) {
      out << "the last " << w << " iterations lowered the energy by less than "
          << 100.0 * options_.progress_tolerance << "% of its fall since the first";
    } else if (options_.motion_tolerance > 0.0 && LastMotionsBelowTolerance(w)) {
      out << "the last " << w << " iterations each moved the output points by less than "
          << options_.motion_tolerance << " noise deviations";
    } else {
      return false;
    }
    Stop(TerminationType::kConvergence, out.str());
    return true;
  }

  // Whether each of the last w motions is at most motion_tolerance x noise_sigma (a NaN
  // motion, iteration 1's, is not).
  bool LastMotionsBelowTolerance(int w) const {
    const std::vector<double>& motions = state_.motion_history;
    const double bar = options_.motion_tolerance * state_.noise_sigma;
    for (size_t j = motions.size() - w; j < motions.size(); ++j) {
      if (!(motions[j] <= bar)) return false;
    }
    return true;
  }

  void Stop(TerminationType termination, const std::string& message) {
    summary_.termination = termination;
    summary_.message = message;
  }

  // Says why max_iters was reached: before GNC got to its targets, or how far from standing
  // still the output is (a slow drift of the plane field where the data leave a tilt
  // undetermined lowers the energy long after the points settle).
  void DescribeNoConvergence() {
    if (!selectivities_.AtTargets(parameters_.mu_l, parameters_.mu_m)) {
      summary_.message = "reached max_iters before graduated non-convexity reached its targets";
      return;
    }
    if (summary_.iterations.empty() || std::isnan(summary_.iterations.back().point_motion)) {
      return;
    }
    const double motion = summary_.iterations.back().point_motion;
    std::ostringstream out;
    out << summary_.message << "; the output points moved " << std::setprecision(2) << motion
        << " of the diagonal (RMS) in the last one";
    if (state_.noise_sigma > 0.0) out << ", " << motion / state_.noise_sigma << " noise sigma";
    summary_.message = out.str();
  }

  const energy::Problem& problem_;
  const SolverSettings& settings_;
  const AlternatingMinimizer::Options& options_;
  energy::Variables* v_;
  MinimizerProgress& state_;
  const int threads_;
  energy::EnergyParameters parameters_;
  SelectivitySchedule selectivities_;  // the targets, or graduated non-convexity's stages
  TangentPlaneSmoother smoother_;
  SolverSummary summary_;
  const Clock::time_point run_start_ = Clock::now();
  double traced_seconds_ = 0.0;  // energy evaluations made only for the trace
};

}  // namespace

SolverSummary AlternatingMinimizer::Minimize(const energy::Problem& problem,
                                             const SolverSettings& settings,
                                             const Options& options, energy::Variables* v,
                                             const IterationCallback& callback,
                                             MinimizerProgress* progress) {
  SolverSummary summary;
  if (!settings.IsValid(&summary.message) || !options.IsValid(&summary.message)) {
    return summary;
  }
  MinimizerProgress local_progress;
  return AlternatingRun(problem, settings, options, v, progress ? progress : &local_progress)
      .Run(callback);
}

}  // namespace lpd::solvers
