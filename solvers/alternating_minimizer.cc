#include "solvers/alternating_minimizer.h"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "energy/energy.h"
#include "energy/fitting_term.h"
#include "energy/smoothness_term.h"
#include "solvers/local_plane_fit.h"
#include "solvers/residual_statistics.h"

namespace lpd::solvers {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

bool AlternatingMinimizer::Options::IsValid(std::string* error) const {
  if (!energy.IsValid(error) || !linear_solver.IsValid(error)) return false;
  std::ostringstream out;
  if (max_iterations < 1) {
    out << "max_iters must be >= 1, got " << max_iterations;
  } else if (inner_iterations < 1) {
    out << "inner_iters must be >= 1, got " << inner_iterations;
  } else if (!(energy_tolerance >= 0.0) || !std::isfinite(energy_tolerance)) {
    out << "energy_tolerance must be finite and >= 0, got " << energy_tolerance;
  } else if (energy_window < 1) {
    out << "energy_window must be >= 1, got " << energy_window;
  } else if (!(mu_l_noise_sigmas >= 0.0) || !std::isfinite(mu_l_noise_sigmas)) {
    out << "mu_l_noise_sigmas must be finite and >= 0, got " << mu_l_noise_sigmas;
  } else if (!gnc.IsValid(error)) {
    return false;
  } else if (num_threads < 1) {
    out << "threads must be >= 1, got " << num_threads;
  } else {
    return true;
  }
  *error = out.str();
  return false;
}

SolverSummary AlternatingMinimizer::Minimize(const energy::Problem& problem,
                                             const Options& options, energy::Variables* v,
                                             const IterationCallback& callback,
                                             MinimizerProgress* progress) {
  SolverSummary summary;
  const Clock::time_point run_start = Clock::now();
  if (!options.IsValid(&summary.message)) return summary;
  MinimizerProgress local_progress;
  MinimizerProgress& state = progress ? *progress : local_progress;

  const int threads = options.num_threads;
  const GncOptions& gnc = options.gnc;
  // The energy of Eq. (5) at the target selectivities; mu_l may still be replaced by the
  // scale-aware value at the first local step.
  energy::EnergyParameters parameters = options.energy;
  if (!std::isnan(state.mu_l)) parameters.mu_l = state.mu_l;
  if (!options.optimize_orientations) v->s.setOnes();
  TangentPlaneSmoother smoother(problem);
  const Clock::time_point initial_start = Clock::now();
  summary.initial_energy = energy::EvaluateEnergy(problem, parameters, *v, threads);
  // Energy evaluations made only for the trace, left out of elapsed_seconds.
  double traced_seconds = SecondsSince(initial_start);

  // Runs one block update, times it and, when tracing, records the energy after it.
  auto run_block = [&](const char* block, int iteration, int inner, auto&& update) {
    const Clock::time_point start = Clock::now();
    StepRecord step;
    step.cg_iterations = update();
    step.seconds = SecondsSince(start);
    step.block = block;
    step.iteration = iteration;
    step.inner_iteration = inner;
    if (options.trace_blocks) {
      const Clock::time_point trace_start = Clock::now();
      step.energy = energy::EvaluateEnergy(problem, parameters, *v, threads);
      traced_seconds += SecondsSince(trace_start);
    }
    summary.steps.push_back(step);
    return step;
  };

  summary.termination = TerminationType::kNoConvergence;
  summary.message = "reached max_iters";
  const int last_iteration = state.iterations + options.max_iterations;
  for (int iteration = state.iterations + 1; iteration <= last_iteration; ++iteration) {
    const Clock::time_point iteration_start = Clock::now();
    const energy::PlaneField previous_t = v->t;
    IterationRecord record;
    record.iteration = iteration;
    // Local tangent-plane fitting step (Alg. 1 lines 9-10).
    record.local_seconds += run_block("H", iteration, 0, [&] {
      UpdateLocalPlanes(problem, parameters, threads, v);
      return -1;
    }).seconds;
    if (std::isnan(state.mu_l)) {  // the first local step fixes the target mu_l
      if (options.mu_l_noise_sigmas > 0.0) {
        parameters.mu_l = NoiseScaledMuL(problem, *v, options.mu_l_noise_sigmas);
      }
      state.mu_l = parameters.mu_l;
    }
    if (gnc.continues_mu_l() && !state.gnc_mu_l.started()) {
      state.gnc_mu_l.Start(gnc, parameters.mu_l, MaxSquaredFittingResidual(problem, *v, threads));
    }
    record.mu_l = state.gnc_mu_l.Value(parameters.mu_l);
    const energy::FittingTerm fitting(problem, record.mu_l, threads);
    record.local_seconds += run_block("L", iteration, 0, [&] {
      fitting.UpdateLineProcesses(v);
      return -1;
    }).seconds;
    // Global piecewise-smoothness step (Alg. 1 lines 12-18).
    for (int inner = 1; inner <= options.inner_iterations; ++inner) {
      const StepRecord t_step = run_block("T", iteration, inner, [&] {
        return smoother.Update(parameters, options.linear_solver, threads, v).iterations;
      });
      record.global_seconds += t_step.seconds;
      record.cg_iterations += t_step.cg_iterations;
      if (gnc.continues_mu_m() && !state.gnc_mu_m.started()) {
        state.gnc_mu_m.Start(gnc, parameters.mu_m,
                             MaxSquaredSmoothnessResidual(problem, *v, threads));
      }
      record.mu_m = state.gnc_mu_m.Value(parameters.mu_m);
      const energy::SmoothnessTerm smoothness(problem, parameters.lambda, record.mu_m, threads);
      record.global_seconds += run_block("M", iteration, inner, [&] {
        smoothness.UpdateLineProcesses(v);
        return -1;
      }).seconds;
      if (options.optimize_orientations) {
        record.global_seconds += run_block("S", iteration, inner, [&] {
          smoothness.UpdateOrientations(v);
          return -1;
        }).seconds;
      }
    }
    record.energy = options.trace_blocks
                        ? summary.steps.back().energy
                        : energy::EvaluateEnergy(problem, parameters, *v, threads);
    if (iteration > 1) {
      record.point_motion = RmsProjectedPointChange(problem, previous_t, v->t, threads);
    }
    record.seconds = SecondsSince(iteration_start);
    record.elapsed_seconds = SecondsSince(run_start) - traced_seconds;
    summary.iterations.push_back(record);
    summary.num_iterations = iteration;
    summary.final_energy = record.energy;
    state.iterations = iteration;

    // The next GNC stage, or none once both continued selectivities are at their targets.
    const bool at_targets = state.gnc_mu_l.AtTarget(parameters.mu_l) &&
                            state.gnc_mu_m.AtTarget(parameters.mu_m);
    if (!at_targets && ++state.stage_iterations == gnc.stage_iterations) {
      state.gnc_mu_l.Shrink(gnc, parameters.mu_l);
      state.gnc_mu_m.Shrink(gnc, parameters.mu_m);
      state.stage_iterations = 0;
    }

    const double total = record.energy.total();
    if (!std::isfinite(total)) {
      summary.termination = TerminationType::kFailure;
      summary.message = "the energy became non-finite at iteration " + std::to_string(iteration);
      break;
    }
    if (callback && !callback(record)) {
      summary.termination = TerminationType::kUserAbort;
      summary.message = "stopped by the callback";
      break;
    }
    if (!at_targets) continue;
    std::vector<double>& history = state.energy_history;
    history.push_back(total);
    const int w = options.energy_window;
    if (options.energy_tolerance > 0.0 && static_cast<int>(history.size()) > w) {
      const double before = history[history.size() - 1 - w];
      if (std::abs(total - before) <= options.energy_tolerance * std::abs(before)) {
        summary.termination = TerminationType::kConvergence;
        std::ostringstream out;
        out << "energy changed by less than " << 100.0 * options.energy_tolerance
            << "% over " << w << " iterations";
        summary.message = out.str();
        break;
      }
    }
  }
  if (summary.termination == TerminationType::kNoConvergence &&
      !(state.gnc_mu_l.AtTarget(parameters.mu_l) && state.gnc_mu_m.AtTarget(parameters.mu_m))) {
    summary.message = "reached max_iters before graduated non-convexity reached its targets";
  } else if (summary.termination == TerminationType::kNoConvergence &&
             !summary.iterations.empty() &&
             !std::isnan(summary.iterations.back().point_motion)) {
    // Say how far from standing still the output is: a slow drift of the plane field where
    // the data leave a tilt undetermined lowers the energy long after the points settle.
    std::ostringstream out;
    out << summary.message << "; the output points moved " << std::setprecision(2)
        << summary.iterations.back().point_motion << " of the diagonal (RMS) in the last one";
    if (options.mu_l_noise_sigmas > 0.0) {
      const double sigma = std::sqrt(parameters.mu_l) / options.mu_l_noise_sigmas;
      out << ", " << summary.iterations.back().point_motion / sigma << " noise sigma";
    }
    summary.message = out.str();
  }
  summary.mu_l = parameters.mu_l;
  summary.eta = parameters.eta;
  summary.lambda = parameters.lambda;
  summary.total_seconds = SecondsSince(run_start);
  return summary;
}

}  // namespace lpd::solvers
