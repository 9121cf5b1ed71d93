// lpd: the unknowns of Eq. (5): planes H and T, line processes L and M, orientations S.
//
// Layout: row i of H and T is the homogeneous plane h_i, t_i in R^4 (plane {q : t^T q = 0},
// q = (p, 1)). Row i of L holds l_ii in column 0 and l_ij for the a-th neighbour j of N(i) in
// column a + 1. M and S hold m_ij and s_ij per pair of M, in graph.pairs order.
#ifndef LPD_ENERGY_VARIABLES_H_
#define LPD_ENERGY_VARIABLES_H_

#include <Eigen/Core>

#include "energy/problem.h"

namespace lpd::energy {

using PlaneField = Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor>;
using LineProcessTable = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct Variables {
  PlaneField h;          // H, n x 4, |h_i| = 1 after the first local step
  PlaneField t;          // T, n x 4
  LineProcessTable l;    // L, n x (k + 1), in [0, 1]
  Eigen::VectorXd m;     // M, one per pair, in [0, 1]
  Eigen::VectorXd s;     // S, one per pair
};

// The initialization of Alg. 1, lines 2-5: H = T = 0, l_ij = m_ij = s_ij = 1, filled by
// `num_threads` threads.
Variables InitialVariables(const Problem& problem, int num_threads = 1);

}  // namespace lpd::energy

#endif  // LPD_ENERGY_VARIABLES_H_
