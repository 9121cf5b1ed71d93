// lpd: what both solvers of Eq. (5) share -- Alg. 1 (alternating_minimizer.h) and the Ceres
// joint solve (ceres_joint_solver.h): the energy's weights, how mu_l follows the noise, and
// the thread count.
#ifndef LPD_SOLVERS_SOLVER_SETTINGS_H_
#define LPD_SOLVERS_SOLVER_SETTINGS_H_

#include <string>

#include "energy/energy_parameters.h"

namespace lpd::solvers {

struct SolverSettings {
  // Eq. (5) and Table 2: lambda, eta, mu_l, mu_m.
  energy::EnergyParameters energy;
  // When > 0, mu_l = (c sigma)^2 with c = mu_l_noise_sigmas and sigma the robust residual
  // scale (residual_statistics.h) of the first fitted planes, replacing energy.mu_l. With
  // c = 3, a residual of one sigma keeps l = 0.81 and one of three sigma l = 0.25 (Eq. 6).
  double mu_l_noise_sigmas = 4.0;
  int num_threads = 1;

  bool IsValid(std::string* error) const;
};

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_SOLVER_SETTINGS_H_
