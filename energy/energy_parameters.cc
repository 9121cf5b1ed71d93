#include "energy/energy_parameters.h"

#include <cmath>
#include <sstream>

namespace lpd::energy {
namespace {

bool CheckPositive(const char* name, double value, std::string* error) {
  if (std::isfinite(value) && value > 0.0) return true;
  std::ostringstream out;
  out << name << " must be finite and > 0, got " << value;
  *error = out.str();
  return false;
}

}  // namespace

bool EnergyParameters::IsValid(std::string* error) const {
  return CheckPositive("lambda", lambda, error) && CheckPositive("eta", eta, error) &&
         CheckPositive("mu_l", mu_l, error) && CheckPositive("mu_m", mu_m, error);
}

}  // namespace lpd::energy
