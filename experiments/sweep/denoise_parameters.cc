#include "experiments/sweep/denoise_parameters.h"

#include <cmath>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace lpd::experiments {
namespace {

using solvers::DenoiseOptions;
using solvers::Solver;

// Which solvers a parameter means something to.
enum class Scope { kBoth, kAlternating, kCeres };

// One tunable value of DenoiseOptions: exactly one kind of accessor is set.
struct Parameter {
  std::string name;
  Scope scope = Scope::kBoth;
  std::function<int&(DenoiseOptions&)> integer;
  std::function<double&(DenoiseOptions&)> number;
  std::function<bool&(DenoiseOptions&)> flag;
  // A named choice: `set_choice` throws std::invalid_argument on an unknown name.
  std::function<std::string(const DenoiseOptions&)> get_choice;
  std::function<void(const std::string&, DenoiseOptions&)> set_choice;
};

Parameter Named(std::string name, Scope scope) {
  Parameter parameter;
  parameter.name = std::move(name);
  parameter.scope = scope;
  return parameter;
}

Parameter Integer(std::string name, Scope scope, std::function<int&(DenoiseOptions&)> field) {
  Parameter parameter = Named(std::move(name), scope);
  parameter.integer = std::move(field);
  return parameter;
}

Parameter Number(std::string name, Scope scope, std::function<double&(DenoiseOptions&)> field) {
  Parameter parameter = Named(std::move(name), scope);
  parameter.number = std::move(field);
  return parameter;
}

Parameter Flag(std::string name, Scope scope, std::function<bool&(DenoiseOptions&)> field) {
  Parameter parameter = Named(std::move(name), scope);
  parameter.flag = std::move(field);
  return parameter;
}

Parameter Choice(std::string name, Scope scope,
                 std::function<std::string(const DenoiseOptions&)> get,
                 std::function<void(const std::string&, DenoiseOptions&)> set) {
  Parameter parameter = Named(std::move(name), scope);
  parameter.get_choice = std::move(get);
  parameter.set_choice = std::move(set);
  return parameter;
}

[[noreturn]] void ThrowUnknownChoice(const std::string& name, const std::string& text,
                                     const std::string& choices) {
  throw std::invalid_argument("parameter " + name + ": '" + text + "' is not one of " + choices);
}

// A choice stored as an enum with a name function and a parser (solvers' Name/Parse pairs).
template <typename Enum, typename NameOf>
Parameter EnumChoice(std::string name, Scope scope, std::function<Enum&(DenoiseOptions&)> field,
                     NameOf name_of, bool (*parse)(const std::string&, Enum*),
                     std::string choices) {
  auto get = [field, name_of](const DenoiseOptions& o) {
    DenoiseOptions copy = o;  // `field` reaches into a mutable DenoiseOptions
    return std::string(name_of(field(copy)));
  };
  auto set = [name, field, parse, choices](const std::string& text, DenoiseOptions& o) {
    if (!parse(text, &field(o))) ThrowUnknownChoice(name, text, choices);
  };
  return Choice(std::move(name), scope, std::move(get), std::move(set));
}

double ParseNumber(const std::string& name, const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value)) {
    throw std::invalid_argument("parameter " + name + ": '" + text + "' is not a number");
  }
  return value;
}

int ParseInteger(const std::string& name, const std::string& text) {
  const double value = ParseNumber(name, text);
  if (value != std::floor(value)) {
    throw std::invalid_argument("parameter " + name + ": '" + text + "' is not an integer");
  }
  if (std::abs(value) > 1e9) {
    throw std::invalid_argument("parameter " + name + ": " + text +
                                " is out of range (at most 1e9 in magnitude)");
  }
  return static_cast<int>(value);
}

// k, the energy's weights and their data rules, the initial state.
std::vector<Parameter> ProblemAndEnergyParameters() {
  using O = DenoiseOptions;
  constexpr Scope kBoth = Scope::kBoth;
  return {
      Choice(
          "k", kBoth,
          [](const O& o) {
            return o.choose_k ? std::string("auto") : std::to_string(o.problem.k);
          },
          [](const std::string& text, O& o) {
            o.choose_k = text == "auto";
            if (o.choose_k) return;
            try {
              o.problem.k = ParseInteger("k", text);
            } catch (const std::invalid_argument&) {
              throw std::invalid_argument("parameter k: '" + text +
                                          "' is neither an integer nor auto");
            }
          }),
      Number("k_radius_sigmas", kBoth,
             [](O& o) -> double& { return o.neighborhood.radius_in_sigmas; }),
      Integer("max_k", kBoth, [](O& o) -> int& { return o.neighborhood.max_k; }),
      Number("max_problem_size", kBoth,
             [](O& o) -> double& { return o.neighborhood.max_problem_size; }),
      Number("lambda", kBoth, [](O& o) -> double& { return o.settings.energy.lambda; }),
      Number("eta", kBoth, [](O& o) -> double& { return o.settings.energy.eta; }),
      Number("mu_l", kBoth, [](O& o) -> double& { return o.settings.energy.mu_l; }),
      Number("mu_m", kBoth, [](O& o) -> double& { return o.settings.energy.mu_m; }),
      Number("fit_balance", kBoth, [](O& o) -> double& { return o.weights.fit_balance; }),
      Number("smoothing_balance", kBoth,
             [](O& o) -> double& { return o.weights.smoothing_balance; }),
      Choice(
          "initialization", kBoth,
          [](const O& o) { return solvers::InitializationName(o.EffectiveInitialization()); },
          [](const std::string& text, O& o) {
            solvers::Initialization initialization;
            if (text == "auto") {
              o.initialization.reset();
            } else if (solvers::ParseInitialization(text, &initialization)) {
              o.initialization = initialization;
            } else {
              ThrowUnknownChoice("initialization", text,
                                 "auto, zero, plane_fit, random, input_normals");
            }
          }),
      Integer("initialization_seed", kBoth,
              [](O& o) -> int& { return o.initialization_seed; }),
  };
}

// Alg. 1's schedule, stopping rule, GNC and T solver; mu_l_noise_sigmas.
std::vector<Parameter> AlternatingParameters() {
  using O = DenoiseOptions;
  constexpr Scope kBoth = Scope::kBoth;
  constexpr Scope kAlternating = Scope::kAlternating;
  return {
      Integer("max_iters", kAlternating, [](O& o) -> int& { return o.minimizer.max_iterations; }),
      Integer("inner_iters", kAlternating,
              [](O& o) -> int& { return o.minimizer.inner_iterations; }),
      Number("energy_tolerance", kAlternating,
             [](O& o) -> double& { return o.minimizer.energy_tolerance; }),
      Number("progress_tolerance", kAlternating,
             [](O& o) -> double& { return o.minimizer.progress_tolerance; }),
      Flag("optimize_orientations", kAlternating,
           [](O& o) -> bool& { return o.minimizer.optimize_orientations; }),
      Number("mu_l_noise_sigmas", kBoth,
             [](O& o) -> double& { return o.settings.mu_l_noise_sigmas; }),
      EnumChoice<solvers::GncTarget>(
          "gnc", kAlternating, [](O& o) -> solvers::GncTarget& { return o.minimizer.gnc.target; },
          solvers::GncTargetName, solvers::ParseGncTarget, "none, mu_l, mu_m, both"),
      Number("gnc_start_ratio", kAlternating,
             [](O& o) -> double& { return o.minimizer.gnc.start_ratio; }),
      Number("gnc_factor", kAlternating, [](O& o) -> double& { return o.minimizer.gnc.factor; }),
      Integer("gnc_stage_iters", kAlternating,
              [](O& o) -> int& { return o.minimizer.gnc.stage_iterations; }),
      Number("linear_tolerance", kAlternating,
             [](O& o) -> double& { return o.minimizer.linear_solver.relative_tolerance; }),
      Integer("max_cg_iterations", kAlternating,
              [](O& o) -> int& { return o.minimizer.linear_solver.max_iterations; }),
      EnumChoice<solvers::Preconditioner>(
          "preconditioner", kAlternating,
          [](O& o) -> solvers::Preconditioner& { return o.minimizer.linear_solver.preconditioner; },
          solvers::PreconditionerName, solvers::ParsePreconditioner, "jacobi, multilevel"),
  };
}

// The Ceres joint solve.
std::vector<Parameter> JointSolveParameters() {
  using O = DenoiseOptions;
  constexpr Scope kCeres = Scope::kCeres;
  return {
      Choice(
          "ceres_orientations", kCeres,
          [](const O& o) {
            return std::string(o.joint.optimize_orientations ? "blocks" : "closed_form");
          },
          [](const std::string& text, O& o) {
            if (text != "blocks" && text != "closed_form") {
              ThrowUnknownChoice("ceres_orientations", text, "blocks, closed_form");
            }
            o.joint.optimize_orientations = text == "blocks";
          }),
      EnumChoice<ceres::LinearSolverType>(
          "ceres_linear_solver", kCeres,
          [](O& o) -> ceres::LinearSolverType& { return o.joint.linear_solver_type; },
          solvers::JointLinearSolverName, solvers::ParseJointLinearSolver,
          "sparse_schur, iterative_schur, sparse_normal_cholesky, cgnr"),
      Integer("ceres_max_iters", kCeres, [](O& o) -> int& { return o.joint.max_iterations; }),
      Number("ceres_function_tolerance", kCeres,
             [](O& o) -> double& { return o.joint.function_tolerance; }),
      Number("ceres_gradient_tolerance", kCeres,
             [](O& o) -> double& { return o.joint.gradient_tolerance; }),
      Number("ceres_parameter_tolerance", kCeres,
             [](O& o) -> double& { return o.joint.parameter_tolerance; }),
      Number("ceres_max_seconds", kCeres, [](O& o) -> double& { return o.joint.max_seconds; }),
  };
}

// The final step of Sec. 3.4: projection, indicators, outlier passes, snapping.
std::vector<Parameter> FinalStepParameters() {
  using O = DenoiseOptions;
  constexpr Scope kBoth = Scope::kBoth;
  return {
      EnumChoice<solvers::Projection>(
          "projection", kBoth,
          [](O& o) -> solvers::Projection& { return o.final_step.projection; },
          solvers::ProjectionName, solvers::ParseProjection, "plane, sphere"),
      Integer("blended_surfaces", kBoth,
              [](O& o) -> int& { return o.final_step.blended_surfaces; }),
      Number("outlier_fraction", kBoth,
             [](O& o) -> double& { return o.final_step.outlier_fraction; }),
      Number("feature_threshold", kBoth,
             [](O& o) -> double& { return o.final_step.feature_line_threshold; }),
      Number("feature_fraction", kBoth,
             [](O& o) -> double& { return o.final_step.feature_fraction; }),
      Flag("remove_outliers", kBoth, [](O& o) -> bool& { return o.final_step.remove_outliers; }),
      Number("max_removed_fraction", kBoth,
             [](O& o) -> double& { return o.final_step.max_removed_fraction; }),
      Integer("outlier_passes", kBoth,
              [](O& o) -> int& { return o.final_step.outlier_passes; }),
      Number("outlier_rerun_fraction", kBoth,
             [](O& o) -> double& { return o.final_step.rerun_removed_fraction; }),
      Number("isolation_factor", kBoth,
             [](O& o) -> double& { return o.final_step.isolation.radius_factor; }),
      Integer("isolation_neighbors", kBoth,
              [](O& o) -> int& { return o.final_step.isolation.neighbors; }),
      Flag("snap_features", kBoth, [](O& o) -> bool& { return o.final_step.snap_features; }),
      Number("snap_cluster_angle_deg", kBoth,
             [](O& o) -> double& { return o.final_step.snapping.cluster_angle_deg; }),
      Integer("snap_min_cluster_planes", kBoth,
              [](O& o) -> int& { return o.final_step.snapping.min_cluster_planes; }),
  };
}

const std::vector<Parameter>& Parameters() {
  static const std::vector<Parameter> parameters = [] {
    std::vector<Parameter> all;
    for (auto group : {ProblemAndEnergyParameters, AlternatingParameters,
                       JointSolveParameters, FinalStepParameters}) {
      for (Parameter& parameter : group()) all.push_back(std::move(parameter));
    }
    return all;
  }();
  return parameters;
}

const Parameter& Find(const std::string& name) {
  for (const Parameter& parameter : Parameters()) {
    if (parameter.name == name) return parameter;
  }
  throw std::invalid_argument("unknown parameter '" + name + "'");
}

// The shortest of 15 or 17 significant digits that reads back as exactly `value` (a saved
// state must resume with the very same doubles).
std::string Text(double value) {
  std::ostringstream out;
  out.precision(15);
  out << value;
  if (std::strtod(out.str().c_str(), nullptr) == value) return out.str();
  out.str("");
  out.precision(17);
  out << value;
  return out.str();
}

}  // namespace

const std::vector<std::string>& DenoiseParameterNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const Parameter& parameter : Parameters()) list.push_back(parameter.name);
    return list;
  }();
  return names;
}

bool DenoiseParameterApplies(const std::string& name, Solver solver) {
  if (name == "mu_m_deg") return true;
  const Scope scope = Find(name).scope;
  return scope == Scope::kBoth ||
         scope == (solver == Solver::kCeres ? Scope::kCeres : Scope::kAlternating);
}

void SetDenoiseParameter(const std::string& name, const std::string& text,
                         DenoiseOptions* options) {
  if (name == "mu_m_deg") {
    const double angle = ParseNumber(name, text);
    if (!(angle > 0.0 && angle < 180.0)) {
      throw std::invalid_argument("parameter mu_m_deg must be in (0, 180), got " + text);
    }
    options->settings.energy.mu_m = 1.0 - std::cos(angle * M_PI / 180.0);
    return;
  }
  const Parameter& parameter = Find(name);
  if (parameter.set_choice) {
    parameter.set_choice(text, *options);
    return;
  }
  if (parameter.flag) {
    if (text == "true" || text == "1") {
      parameter.flag(*options) = true;
    } else if (text == "false" || text == "0") {
      parameter.flag(*options) = false;
    } else {
      throw std::invalid_argument("parameter " + name + ": '" + text + "' is not true or false");
    }
    return;
  }
  if (parameter.number) {
    parameter.number(*options) = ParseNumber(name, text);
    // A weight given outright replaces the rule that would derive it from the data; a
    // later rule parameter (they come after the weights) switches the rule back on.
    if (name == "eta") options->weights.fit_balance = 0.0;
    if (name == "lambda") options->weights.smoothing_balance = 0.0;
    if (name == "mu_l") options->settings.mu_l_noise_sigmas = 0.0;
  } else {
    parameter.integer(*options) = ParseInteger(name, text);
  }
}

std::string GetDenoiseParameter(const std::string& name, const DenoiseOptions& options) {
  DenoiseOptions copy = options;  // the accessors hand out mutable references
  if (name == "mu_m_deg") {
    return Text(std::acos(1.0 - copy.settings.energy.mu_m) * 180.0 / M_PI);
  }
  const Parameter& parameter = Find(name);
  if (parameter.get_choice) return parameter.get_choice(copy);
  if (parameter.flag) return parameter.flag(copy) ? "true" : "false";
  if (parameter.number) return Text(parameter.number(copy));
  return std::to_string(parameter.integer(copy));
}

}  // namespace lpd::experiments
