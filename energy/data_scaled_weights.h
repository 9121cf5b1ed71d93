// lpd: the weights eta and lambda of Eq. (5) derived from the data instead of given as
// constants, so that one default holds for any bounding box, density and k.
//
// Per point, a tilt theta of h_i away from its fitted plane costs the fitting term about
// (k + 1) alpha_i theta^2 (k + 1 residuals over a neighbourhood of mean squared radius
// alpha_i) and the stitching term eta alpha_i theta^2. Their ratio
//   fit_balance       F = eta / ((k + 1) median_i alpha_i)
// says whether h_i follows the data (F <~ 1) or the smoothed plane t_i (F >> 1). The
// paper's eta = 5000 puts F near 1e6 on its inputs, where the data term is inert after the
// first local fit and Alg. 1 drifts toward the degenerate minimum of all planes equal.
// In the T system (Eq. 9) the smoothness share of K's diagonal over the stitching share,
//   smoothing_balance B = median_i lambda sum_{j: ij in M} beta_ij / (eta alpha_i),
// is the squared smoothing radius in neighbour hops (energy/term_balance.h). Both ratios are
// dimensionless: alpha_i scales with the squared neighbour distance and beta_ij not at all, so
// fixed F and B give the same energy, up to a constant factor, for any scale and density.
#ifndef LPD_ENERGY_DATA_SCALED_WEIGHTS_H_
#define LPD_ENERGY_DATA_SCALED_WEIGHTS_H_

#include <string>

#include "energy/energy_parameters.h"
#include "energy/problem.h"

namespace lpd::energy {

struct DataScaledWeights {
  // F above; 0 keeps the given eta.
  double fit_balance = 0.5;
  // B above; 0 keeps the given lambda.
  double smoothing_balance = 4.0;

  bool IsValid(std::string* error) const;
};

// `parameters` with eta set from fit_balance and lambda from smoothing_balance (each only
// when its ratio is > 0); mu_l and mu_m unchanged. Deterministic in `problem`, whatever
// `num_threads`.
EnergyParameters ScaleWeightsToData(const Problem& problem, const EnergyParameters& parameters,
                                    const DataScaledWeights& weights, int num_threads = 1);

}  // namespace lpd::energy

#endif  // LPD_ENERGY_DATA_SCALED_WEIGHTS_H_
