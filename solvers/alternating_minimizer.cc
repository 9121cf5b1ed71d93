#include "solvers/alternating_minimizer.h"

#include <chrono>
#include <cmath>
#include <sstream>

#include "energy/energy.h"
#include "energy/fitting_term.h"
#include "energy/smoothness_term.h"
#include "solvers/local_plane_fit.h"

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
                                             const IterationCallback& callback) {
  SolverSummary summary;
  const Clock::time_point run_start = Clock::now();
  if (!options.IsValid(&summary.message)) return summary;

  const int threads = options.num_threads;
  const energy::EnergyParameters& parameters = options.energy;
  const energy::FittingTerm fitting(problem, parameters.mu_l, threads);
  const energy::SmoothnessTerm smoothness(problem, parameters.lambda, parameters.mu_m, threads);
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

  std::vector<double> history;
  summary.termination = TerminationType::kNoConvergence;
  summary.message = "reached max_iters";
  for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
    const Clock::time_point iteration_start = Clock::now();
    IterationRecord record;
    record.iteration = iteration;
    // Local tangent-plane fitting step (Alg. 1 lines 9-10).
    record.local_seconds += run_block("H", iteration, 0, [&] {
      UpdateLocalPlanes(problem, parameters, threads, v);
      return -1;
    }).seconds;
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
      record.global_seconds += run_block("M", iteration, inner, [&] {
        smoothness.UpdateLineProcesses(v);
        return -1;
      }).seconds;
      record.global_seconds += run_block("S", iteration, inner, [&] {
        smoothness.UpdateOrientations(v);
        return -1;
      }).seconds;
    }
    record.energy = options.trace_blocks
                        ? summary.steps.back().energy
                        : energy::EvaluateEnergy(problem, parameters, *v, threads);
    record.seconds = SecondsSince(iteration_start);
    record.elapsed_seconds = SecondsSince(run_start) - traced_seconds;
    summary.iterations.push_back(record);
    summary.num_iterations = iteration;
    summary.final_energy = record.energy;

    const double total = record.energy.total();
    if (!std::isfinite(total)) {
      summary.termination = TerminationType::kFailure;
      summary.message = "the energy became non-finite at iteration " + std::to_string(iteration);
      break;
    }
    history.push_back(total);
    if (callback && !callback(record)) {
      summary.termination = TerminationType::kUserAbort;
      summary.message = "stopped by the callback";
      break;
    }
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
  summary.total_seconds = SecondsSince(run_start);
  return summary;
}

}  // namespace lpd::solvers
