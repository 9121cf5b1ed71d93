// lpd: the total energy of Eq. (5) with its per-term breakdown.
#ifndef LPD_ENERGY_ENERGY_H_
#define LPD_ENERGY_ENERGY_H_

#include "energy/energy_parameters.h"
#include "energy/problem.h"
#include "energy/variables.h"

namespace lpd::energy {

struct EnergyBreakdown {
  double fitting = 0.0;     // 1/2 sum alpha_i [ (h_i^T q_j)^2 l_ij + Psi(l_ij) ]
  double smoothness = 0.0;  // lambda/2 sum beta_ij [ |t_i - s_ij t_j|^2 m_ij + Psi(m_ij) ]
  double stitching = 0.0;   // eta/2 sum alpha_i |h_i - t_i|^2

  double total() const { return fitting + smoothness + stitching; }
};

EnergyBreakdown EvaluateEnergy(const Problem& problem, const EnergyParameters& parameters,
                               const Variables& v, int num_threads = 1);

}  // namespace lpd::energy

#endif  // LPD_ENERGY_ENERGY_H_
