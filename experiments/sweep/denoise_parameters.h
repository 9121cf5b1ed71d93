// lpd: the denoiser's tunable parameters by name, shared by the command-line flags of
// `lpd denoise` / `lpd bench` and the method grids of sweep configs, so that both spell and
// check every parameter the same way.
#ifndef LPD_EXPERIMENTS_SWEEP_DENOISE_PARAMETERS_H_
#define LPD_EXPERIMENTS_SWEEP_DENOISE_PARAMETERS_H_

#include <string>
#include <vector>

#include "solvers/denoise_point_set.h"

namespace lpd::experiments {

// The parameter names, in a fixed order (the order of result columns).
const std::vector<std::string>& DenoiseParameterNames();

// Whether parameter `name` has any effect with `solver` (the schedule of Alg. 1 does not
// apply to the joint solve, nor the ceres_* options to Alg. 1). Throws for an unknown name.
bool DenoiseParameterApplies(const std::string& name, solvers::Solver solver);

// Sets parameter `name` of `options` from `text`. Throws std::invalid_argument naming the
// parameter if it is unknown or `text` is not a valid value of its type (int, number, bool,
// or one of a parameter's named choices).
// "mu_m_deg" sets mu_m = 1 - cos(angle) (the reference implementation's angle form).
// "eta", "lambda" and "mu_l" also switch off the data rule for that weight (fit_balance,
// smoothing_balance, mu_l_noise_sigmas = 0), so a weight given outright is the one used.
void SetDenoiseParameter(const std::string& name, const std::string& text,
                         solvers::DenoiseOptions* options);

// The current value of parameter `name` as text ("mu_m_deg" gives the angle of mu_m).
std::string GetDenoiseParameter(const std::string& name, const solvers::DenoiseOptions& options);

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_SWEEP_DENOISE_PARAMETERS_H_
