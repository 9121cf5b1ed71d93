// lpd: how strongly the smoothness term couples the planes against the stitching term that
// holds each one in place, the number that decides how hard the T system of Eq. (9) is.
//
// With every m_ij = s_ij = 1, K's diagonal is eta alpha_i (stitching) plus
// lambda sum_{j: ij in M} beta_ij (smoothness). Their ratio
//   rho_i = lambda sum_j beta_ij / (eta alpha_i)
// goes like (lambda / eta) / alpha_i, the squared smoothing length sqrt(lambda / eta) over a
// squared neighbour distance (beta_ij ~ alpha / (k |p_i - p_j|^2) sums to a few units). A
// small rho keeps K close to its diagonal; a large one makes it close to a graph Laplacian,
// which takes a multigrid solver more iterations. At a fixed eta, rho grows with the
// sampling density (docs/performance.md).
#ifndef LPD_ENERGY_TERM_BALANCE_H_
#define LPD_ENERGY_TERM_BALANCE_H_

#include "energy/energy_parameters.h"
#include "energy/problem.h"

namespace lpd::energy {

// The median over the points of rho_i (0 for an empty problem), with `num_threads` threads.
double MedianSmoothnessToStitchingRatio(const Problem& problem,
                                        const EnergyParameters& parameters,
                                        int num_threads = 1);

}  // namespace lpd::energy

#endif  // LPD_ENERGY_TERM_BALANCE_H_
