// lpd: the robust piecewise-smoothness term of Eq. (5), its feature line processes M and
// the orientations S.
//
//   E_smooth = lambda/2 sum_{(i,j) in M} beta_ij [ |t_i - s_ij t_j|^2 m_ij + Psi_mu_m(m_ij) ]
// with each pair stored once as i < j. UpdateLineProcesses applies Eq. (7) and
// UpdateOrientations Eq. (8); each is the exact minimizer of E_smooth over its block.
#ifndef LPD_ENERGY_SMOOTHNESS_TERM_H_
#define LPD_ENERGY_SMOOTHNESS_TERM_H_

#include "energy/geman_mcclure.h"
#include "energy/problem.h"
#include "energy/variables.h"

namespace ceres {
class Problem;
}  // namespace ceres

namespace lpd::energy {

class SmoothnessTerm {
 public:
  SmoothnessTerm(const Problem& problem, double lambda, double mu_m, int num_threads = 1)
      : problem_(problem), lambda_(lambda), penalty_(mu_m), num_threads_(num_threads) {}

  // E_smooth at `v` (uses v.t, v.m, v.s), including the factor lambda.
  double Evaluate(const Variables& v) const;

  // m_ij = (mu_m / (mu_m + |t_i - s_ij t_j|^2))^2 (Eq. 7).
  void UpdateLineProcesses(Variables* v) const;

  // s_ij = t_i^T t_j / t_j^T t_j (Eq. 8); left unchanged where t_j = 0 (any s is optimal).
  void UpdateOrientations(Variables* v) const;

  // Adds one residual per pair of M with loss lambda beta_ij rho_mu_m, on the parameter
  // blocks v->t (rows) and, if `optimize_orientations`, v->s (one scalar block per pair):
  // f = t_i - s_ij t_j. Otherwise s_ij is held at its optimum (Eq. 8) inside the residual.
  // `problem` must own its cost and loss functions and must not outlive `v`.
  void AddResiduals(Variables* v, bool optimize_orientations, ceres::Problem* problem) const;

  // |t_i - s_ij t_j|^2 for pair `p`.
  double SquaredDifference(const Variables& v, int p) const {
    const auto& pair = problem_.graph.pairs[p];
    return (v.t.row(pair[0]) - v.s[p] * v.t.row(pair[1])).squaredNorm();
  }

 private:
  const Problem& problem_;
  double lambda_;
  GemanMcClure penalty_;
  int num_threads_;
};

}  // namespace lpd::energy

#endif  // LPD_ENERGY_SMOOTHNESS_TERM_H_
