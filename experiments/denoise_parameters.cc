#include "experiments/denoise_parameters.h"

#include <cmath>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace lpd::experiments {
namespace {

using solvers::DenoiseOptions;

// One tunable value of DenoiseOptions: exactly one of the three accessors is set.
struct Parameter {
  std::string name;
  std::function<int&(DenoiseOptions&)> integer;
  std::function<double&(DenoiseOptions&)> number;
  std::function<bool&(DenoiseOptions&)> flag;
};

const std::vector<Parameter>& Parameters() {
  using O = DenoiseOptions;
  static const std::vector<Parameter> parameters = {
      {"k", [](O& o) -> int& { return o.problem.k; }, {}, {}},
      {"lambda", {}, [](O& o) -> double& { return o.minimizer.energy.lambda; }, {}},
      {"eta", {}, [](O& o) -> double& { return o.minimizer.energy.eta; }, {}},
      {"mu_l", {}, [](O& o) -> double& { return o.minimizer.energy.mu_l; }, {}},
      {"mu_m", {}, [](O& o) -> double& { return o.minimizer.energy.mu_m; }, {}},
      {"max_iters", [](O& o) -> int& { return o.minimizer.max_iterations; }, {}, {}},
      {"inner_iters", [](O& o) -> int& { return o.minimizer.inner_iterations; }, {}, {}},
      {"energy_tolerance", {}, [](O& o) -> double& { return o.minimizer.energy_tolerance; }, {}},
      {"linear_tolerance", {},
       [](O& o) -> double& { return o.minimizer.linear_solver.relative_tolerance; }, {}},
      {"max_cg_iterations", [](O& o) -> int& { return o.minimizer.linear_solver.max_iterations; },
       {}, {}},
      {"outlier_threshold", {},
       [](O& o) -> double& { return o.final_step.outlier_line_threshold; }, {}},
      {"outlier_fraction", {}, [](O& o) -> double& { return o.final_step.outlier_fraction; }, {}},
      {"feature_threshold", {},
       [](O& o) -> double& { return o.final_step.feature_line_threshold; }, {}},
      {"feature_fraction", {}, [](O& o) -> double& { return o.final_step.feature_fraction; }, {}},
      {"remove_outliers", {}, {}, [](O& o) -> bool& { return o.final_step.remove_outliers; }},
      {"max_removed_fraction", {},
       [](O& o) -> double& { return o.final_step.max_removed_fraction; }, {}},
  };
  return parameters;
}

const Parameter& Find(const std::string& name) {
  for (const Parameter& parameter : Parameters()) {
    if (parameter.name == name) return parameter;
  }
  throw std::invalid_argument("unknown parameter '" + name + "' of method lpd");
}

double ParseNumber(const std::string& name, const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value)) {
    throw std::invalid_argument("parameter " + name + ": '" + text + "' is not a number");
  }
  return value;
}

std::string Text(double value) {
  std::ostringstream out;
  out.precision(12);
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

void SetDenoiseParameter(const std::string& name, const std::string& text,
                         DenoiseOptions* options) {
  if (name == "mu_m_deg") {
    const double angle = ParseNumber(name, text);
    if (!(angle > 0.0 && angle < 180.0)) {
      throw std::invalid_argument("parameter mu_m_deg must be in (0, 180), got " + text);
    }
    options->minimizer.energy.mu_m = 1.0 - std::cos(angle * M_PI / 180.0);
    return;
  }
  const Parameter& parameter = Find(name);
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
  const double value = ParseNumber(name, text);
  if (parameter.number) {
    parameter.number(*options) = value;
  } else if (value != std::floor(value) || std::abs(value) > 1e9) {
    throw std::invalid_argument("parameter " + name + ": '" + text + "' is not an integer");
  } else {
    parameter.integer(*options) = static_cast<int>(value);
  }
}

std::string GetDenoiseParameter(const std::string& name, const DenoiseOptions& options) {
  DenoiseOptions copy = options;  // the accessors hand out mutable references
  if (name == "mu_m_deg") {
    return Text(std::acos(1.0 - copy.minimizer.energy.mu_m) * 180.0 / M_PI);
  }
  const Parameter& parameter = Find(name);
  if (parameter.flag) return parameter.flag(copy) ? "true" : "false";
  if (parameter.number) return Text(parameter.number(copy));
  return std::to_string(parameter.integer(copy));
}

}  // namespace lpd::experiments
