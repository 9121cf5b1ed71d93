// lpd: the local step of Alg. 1 (line 9): every h_i by Eq. (10), in parallel.
//
//   h_i = argmin_{|h| = 1} 1/2 h^T A_i h - b_i^T h,
//   A_i = alpha_i (eta I + sum_{j in N(i) u {i}} l_ij q_j q_j^T),   b_i = eta alpha_i t_i,
// which is the exact minimizer of E_fit + E_stitch over h_i (Sec. 3.3).
#ifndef LPD_SOLVERS_LOCAL_PLANE_FIT_H_
#define LPD_SOLVERS_LOCAL_PLANE_FIT_H_

#include "energy/energy_parameters.h"
#include "energy/problem.h"
#include "energy/variables.h"

namespace lpd::solvers {

// A_i and b_i of Eq. (10) for point i.
void LocalPlaneSystem(const energy::Problem& problem, const energy::EnergyParameters& parameters,
                      const energy::Variables& v, int i, Eigen::Matrix4d* a,
                      Eigen::Vector4d* b);

// Replaces every h_i of `v` by the minimizer of Eq. (10).
void UpdateLocalPlanes(const energy::Problem& problem, const energy::EnergyParameters& parameters,
                       int num_threads, energy::Variables* v);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_LOCAL_PLANE_FIT_H_
