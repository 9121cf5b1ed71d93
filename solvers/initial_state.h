// lpd: where a minimization of Eq. (5) starts.
//
//   kZero       Alg. 1 lines 2-5: H = T = 0, L = M = S = 1. The energy there is 0 and h_i is
//               off the unit sphere, so only the alternating driver can start from it (its
//               first local step puts every h_i on the sphere).
//   kPlaneFit   the state after Alg. 1's first local step from kZero: every h_i is the
//               PCA plane of N(i) u {i} (Eq. 10 with l = 1 and t = 0); then T = H, S by
//               Eq. (8), L by Eq. (6) and M by Eq. (7). Both solvers can start here, which
//               is how they are compared from the same state.
#ifndef LPD_SOLVERS_INITIAL_STATE_H_
#define LPD_SOLVERS_INITIAL_STATE_H_

#include <string>

#include "energy/energy_parameters.h"
#include "energy/problem.h"
#include "energy/variables.h"

namespace lpd::solvers {

enum class Initialization { kZero, kPlaneFit };

const char* InitializationName(Initialization initialization);  // "zero", "plane_fit"
// False if `name` is neither.
bool ParseInitialization(const std::string& name, Initialization* initialization);

energy::Variables InitialState(const energy::Problem& problem,
                               const energy::EnergyParameters& parameters,
                               Initialization initialization, int num_threads);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_INITIAL_STATE_H_
