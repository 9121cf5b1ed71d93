// lpd: where a minimization of Eq. (5) starts.
//
//   kZero          Alg. 1 lines 2-5: H = T = 0, L = M = S = 1. The energy there is 0 and h_i
//                  is off the unit sphere, so only the alternating driver can start from it
//                  (its first local step puts every h_i on the sphere).
//   kPlaneFit      every h_i is the PCA plane of N(i) u {i} (Eq. 10 with l = 1 and t = 0),
//                  the state after Alg. 1's first local step from kZero (Sec. 3.5).
//   kRandom        every h_i uniform on the unit sphere of R^4 (seeded), as the public
//                  reference implementation starts.
//   kInputNormals  every h_i the plane through p_i with the given normal n_i.
// Except for kZero, T = H, and S, M, L follow from Eqs. (8), (7), (6): a consistent state
// both solvers can start from, which is how they are compared from the same state.
#ifndef LPD_SOLVERS_INITIAL_STATE_H_
#define LPD_SOLVERS_INITIAL_STATE_H_

#include <cstdint>
#include <string>

#include "energy/energy_parameters.h"
#include "energy/problem.h"
#include "energy/variables.h"

namespace lpd::solvers {

enum class Initialization { kZero, kPlaneFit, kRandom, kInputNormals };

// "zero", "plane_fit", "random", "input_normals"
const char* InitializationName(Initialization initialization);
// False if `name` is none of those.
bool ParseInitialization(const std::string& name, Initialization* initialization);

// `seed` is used by kRandom; `normals` (one per problem point, any length but zero) by
// kInputNormals. Throws std::invalid_argument if kInputNormals has no usable normals.
energy::Variables InitialState(const energy::Problem& problem,
                               const energy::EnergyParameters& parameters,
                               Initialization initialization, int num_threads,
                               uint64_t seed = 1, const energy::PointList* normals = nullptr);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_INITIAL_STATE_H_
