#include "energy/data_scaled_weights.h"

#include <cmath>
#include <sstream>

#include "energy/term_balance.h"

namespace lpd::energy {
namespace {

bool FiniteNonNegative(double x) { return std::isfinite(x) && x >= 0.0; }

}  // namespace

bool DataScaledWeights::IsValid(std::string* error) const {
  std::ostringstream out;
  if (!FiniteNonNegative(fit_balance)) {
    out << "fit_balance must be finite and >= 0, got " << fit_balance;
  } else if (!FiniteNonNegative(smoothing_balance)) {
    out << "smoothing_balance must be finite and >= 0, got " << smoothing_balance;
  } else {
    return true;
  }
  *error = out.str();
  return false;
}

EnergyParameters ScaleWeightsToData(const Problem& problem, const EnergyParameters& parameters,
                                    const DataScaledWeights& weights, int num_threads) {
  EnergyParameters scaled = parameters;
  if (problem.num_points() == 0) return scaled;
  if (weights.fit_balance > 0.0) {
    scaled.eta = weights.fit_balance * (problem.k() + 1) * MedianAlpha(problem);
  }
  if (weights.smoothing_balance > 0.0) {
    EnergyParameters unit = scaled;
    unit.lambda = 1.0;
    scaled.lambda =
        weights.smoothing_balance / MedianSmoothnessToStitchingRatio(problem, unit, num_threads);
  }
  return scaled;
}

}  // namespace lpd::energy
