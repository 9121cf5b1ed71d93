#include "experiments/sweep/sweep_methods.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <stdexcept>

#include "experiments/baselines/cgal_baselines.h"
#include "io/interruption.h"
#include "lpd/options.h"
#include "lpd/parameters.h"
#include "experiments/sweep/method_parameters.h"
#include "solvers/denoise_point_set.h"
#include "lpd/presets.h"

namespace lpd::experiments {
namespace {

// The solver behind a method that runs DenoisePointSet; false for other methods.
bool DenoiseSolver(const std::string& method, solvers::Solver* solver) {
  if (method == "lpd") {
    *solver = solvers::Solver::kAlternating;
  } else if (method == "ceres") {
    *solver = solvers::Solver::kCeres;
  } else {
    return false;
  }
  return true;
}

// The options of a method cell: its parameters go through the same declarations as the
// flags of `lpd denoise` (lpd/options.h); errors name the method.
solvers::DenoiseOptions DenoiseOptionsOf(const MethodConfig& method, solvers::Solver solver) {
  try {
    std::string preset = "default";
    for (const auto& [name, value] : method.parameters) {
      if (name == "preset") preset = value.text;
    }
    Options options(preset);
    options.solver = solvers::SolverName(solver);
    for (const auto& [name, value] : method.parameters) {
      if (name != "preset") options.Set(name, value.text);
    }
    return ResolveOptions(options);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument("method " + method.method + ": " + error.what());
  }
}

MethodRun RunDenoiser(const MethodConfig& method, solvers::Solver solver,
                      const energy::PointList& input, int num_threads) {
  solvers::DenoiseOptions options = DenoiseOptionsOf(method, solver);
  options.settings.num_threads = num_threads;
  options.minimizer.trace_blocks = false;
  solvers::DenoiseHooks hooks;
  hooks.progress = [](const solvers::IterationRecord&) { return !io::InterruptionRequested(); };
  const solvers::DenoiseResult result = solvers::DenoisePointSet(input, options, hooks);
  io::ThrowIfInterrupted();  // a run stopped by a signal is no result
  MethodRun run;
  for (size_t i = 0; i < input.size(); ++i) {
    if (result.kept[i]) run.output.push_back(result.projected[i]);
  }
  run.outlier_flags = result.indicators.is_outlier;
  run.feature_flags = result.indicators.is_feature;
  const solvers::SolverSummary& summary = result.summary;
  run.iterations = summary.num_iterations;
  run.initial_energy = summary.initial_energy.total();
  run.final_energy = summary.final_energy.total();
  run.seconds = result.total_seconds;
  run.setup_seconds = result.setup_seconds;
  run.energy_trace.emplace_back(0.0, run.initial_energy);
  for (const solvers::IterationRecord& record : summary.iterations) {
    run.energy_trace.emplace_back(record.elapsed_seconds, record.energy.total());
    run.energy_terms.push_back(record.energy);
    run.local_seconds += record.local_seconds / summary.iterations.size();
    run.global_seconds += record.global_seconds / summary.iterations.size();
  }
  if (solver == solvers::Solver::kCeres) {  // the joint solve has no local / global steps
    run.local_seconds = NAN;
    run.global_seconds = NAN;
  }
  run.mu_l = summary.mu_l;
  run.termination = solvers::TerminationTypeName(summary.termination);
  run.note = result.removal_note;
  return run;
}

// A CGAL baseline with its options read from `method` (effective values in `values`).
// Null for a method that is not a baseline.
using Smoother = std::function<energy::PointList(const energy::PointList&)>;

Smoother Baseline(const MethodConfig& method,
                  std::vector<std::pair<std::string, std::string>>* values) {
  MethodParameters parameters(method);
  Smoother smooth;
  if (method.method == "bilateral") {
    BilateralOptions options;
    options.k = parameters.Integer("k", options.k, 3);
    options.sharpness_angle_deg =
        parameters.Number("sharpness_angle", options.sharpness_angle_deg, 0.1, 89.9);
    options.iterations = parameters.Integer("iterations", options.iterations, 1);
    options.normals = ParseNormalEstimator(
        parameters.Choice("normals", ToString(options.normals), {"pca", "jet"}));
    smooth = [options](const energy::PointList& input) { return BilateralSmooth(input, options); };
  } else if (method.method == "jet") {
    JetOptions options;
    options.k = parameters.Integer("k", options.k, 6);
    options.iterations = parameters.Integer("iterations", options.iterations, 1);
    smooth = [options](const energy::PointList& input) { return JetSmooth(input, options); };
  } else if (method.method == "wlop") {
    WlopOptions options;
    options.select_percentage =
        parameters.Number("select_percentage", options.select_percentage, 0.1, 100.0);
    options.radius_spacings =
        parameters.Number("radius_spacings", options.radius_spacings, 0.1, 100.0);
    options.iterations = parameters.Integer("iterations", options.iterations, 1);
    smooth = [options](const energy::PointList& input) { return WlopResample(input, options); };
  } else {
    return nullptr;
  }
  *values = parameters.Finish();
  return smooth;
}

}  // namespace

const std::vector<std::string>& MethodNames() {
  static const std::vector<std::string> names = {"none", "lpd", "ceres", "bilateral", "jet",
                                                 "wlop"};
  return names;
}

std::vector<std::pair<std::string, std::string>> EffectiveParameters(
    const MethodConfig& method) {
  std::vector<std::pair<std::string, std::string>> values;
  solvers::Solver solver;
  if (method.method == "none") {
    if (!method.parameters.empty()) {
      throw std::invalid_argument("method none takes no parameters (got '" +
                                  method.parameters.begin()->first + "')");
    }
  } else if (DenoiseSolver(method.method, &solver)) {
    const solvers::DenoiseOptions options = DenoiseOptionsOf(method, solver);
    for (const std::string& name : DenoiseParameterNames()) {
      if (DenoiseParameterApplies(name, solver)) {
        values.emplace_back(name, GetDenoiseParameter(name, options));
      }
    }
  } else if (!Baseline(method, &values)) {
    std::string known;
    for (const std::string& name : MethodNames()) known += (known.empty() ? "" : ", ") + name;
    throw std::invalid_argument("unknown method '" + method.method + "' (known: " + known + ")");
  }
  return values;
}

MethodRun RunMethod(const MethodConfig& method, const energy::PointList& input, int num_threads) {
  solvers::Solver solver;
  if (DenoiseSolver(method.method, &solver)) return RunDenoiser(method, solver, input, num_threads);
  std::vector<std::pair<std::string, std::string>> unused_values;
  const Smoother smooth = Baseline(method, &unused_values);
  MethodRun run;
  if (!smooth) {
    EffectiveParameters(method);  // throws unless the method is "none" without parameters
    run.output = input;
    return run;
  }
  const auto start = std::chrono::steady_clock::now();
  run.output = smooth(input);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace lpd::experiments
