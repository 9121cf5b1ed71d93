// lpd: every tunable parameter of a denoising run, declared once.
//
// One declaration per parameter (parameters.cc) gives its name, kind, the solvers it applies
// to, its --help group and text, how its default is derived from the data when it is, and
// the paper's value. Everything else is generated from it: the flags of `lpd denoise` and
// `lpd bench`, the keys of sweep configs, the fields of saved states, the options of the C++
// API (lpd/denoise.h) and of the Python module, the paper preset (lpd/presets.h), and --help.
// A parameter's default is the default solvers::DenoiseOptions' value ("auto" for the four
// derived from the data: k, eta, lambda, mu_l).
#ifndef LPD_PARAMETERS_H_
#define LPD_PARAMETERS_H_

#include <string>
#include <utility>
#include <vector>

#include "solvers/denoise_point_set.h"

namespace lpd {

enum class ParameterKind { kInteger, kNumber, kFlag, kChoice };

// Which solvers a parameter means something to.
enum class ParameterScope { kBoth, kAlternating, kCeres };

struct ParameterInfo {
  std::string name;
  ParameterKind kind = ParameterKind::kNumber;
  ParameterScope scope = ParameterScope::kBoth;
  std::string group;        // heading in --help
  std::string help;         // one sentence or two, without the default
  // How "auto" derives the value from the data; empty when the parameter has no auto.
  std::string auto_rule;
  // The paper's value (Table 2, Alg. 1, Sec. 3.4) as text; empty when the paper preset
  // keeps the default.
  std::string paper_value;
};

// The declarations, in a fixed order (the order of --help, result columns and state files).
const std::vector<ParameterInfo>& DenoiseParameters();
const std::vector<std::string>& DenoiseParameterNames();
// The declaration called `name`; throws std::invalid_argument for an unknown name.
const ParameterInfo& FindDenoiseParameter(const std::string& name);

// Whether parameter `name` has any effect with `solver` (the schedule of Alg. 1 does not
// apply to the joint solve, nor the ceres_* options to Alg. 1). Throws for an unknown name.
bool DenoiseParameterApplies(const std::string& name, solvers::Solver solver);

// Sets parameter `name` of `options` from `text`. Throws std::invalid_argument naming the
// parameter if it is unknown or `text` is not a valid value of its kind (integer, number,
// true/false, one of its named choices, or auto where it has a data rule).
// "mu_m_deg" sets mu_m = 1 - cos(angle) (the reference implementation's angle form).
// A number given for "eta", "lambda" or "mu_l" switches off the data rule of that weight
// (fit_balance, smoothing_balance, mu_l_noise_sigmas = 0), so a weight given outright is the
// one used; "auto" switches the rule back on with its default.
void SetDenoiseParameter(const std::string& name, const std::string& text,
                         solvers::DenoiseOptions* options);

// The current value of parameter `name` as text that SetDenoiseParameter reads back to the
// very same value ("auto" while a weight follows its data rule; "mu_m_deg" gives the angle).
std::string GetDenoiseParameter(const std::string& name, const solvers::DenoiseOptions& options);

// The pairs of parameters of which at most one may be given: a weight and its data rule
// (eta and fit_balance, ...), mu_m and mu_m_deg, k and the parameters of auto k. Throws
// std::invalid_argument naming both when `given` (name, value) holds both of a pair and the
// first is not "auto".
void RefuseConflictingParameters(
    const std::vector<std::pair<std::string, std::string>>& given);

}  // namespace lpd

#endif  // LPD_PARAMETERS_H_
