#include "solvers/solver_settings.h"

#include <cmath>
#include <sstream>

namespace lpd::solvers {

bool SolverSettings::IsValid(std::string* error) const {
  if (!energy.IsValid(error)) return false;
  std::ostringstream out;
  if (!(mu_l_noise_sigmas >= 0.0) || !std::isfinite(mu_l_noise_sigmas)) {
    out << "mu_l_noise_sigmas must be finite and >= 0, got " << mu_l_noise_sigmas;
  } else if (num_threads < 1) {
    out << "threads must be >= 1, got " << num_threads;
  } else {
    return true;
  }
  *error = out.str();
  return false;
}

}  // namespace lpd::solvers
