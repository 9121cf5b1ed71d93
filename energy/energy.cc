#include "energy/energy.h"

#include "energy/fitting_term.h"
#include "energy/smoothness_term.h"
#include "energy/stitching_term.h"

namespace lpd::energy {

EnergyBreakdown EvaluateEnergy(const Problem& problem, const EnergyParameters& parameters,
                               const Variables& v, int num_threads) {
  EnergyBreakdown e;
  e.fitting = FittingTerm(problem, parameters.mu_l, num_threads).Evaluate(v);
  e.smoothness =
      SmoothnessTerm(problem, parameters.lambda, parameters.mu_m, num_threads).Evaluate(v);
  e.stitching = StitchingTerm(problem, parameters.eta, num_threads).Evaluate(v);
  return e;
}

}  // namespace lpd::energy
