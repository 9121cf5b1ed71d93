// lpd: the robust local-fitting term of Eq. (5) and its outlier line processes L.
//
//   E_fit = 1/2 sum_i sum_{j in N(i) u {i}} alpha_i [ (h_i^T q_j)^2 l_ij + Psi_mu_l(l_ij) ]
// UpdateLineProcesses sets every l_ij to its closed-form minimizer, Eq. (6).
#ifndef LPD_ENERGY_FITTING_TERM_H_
#define LPD_ENERGY_FITTING_TERM_H_

#include "energy/geman_mcclure.h"
#include "energy/problem.h"
#include "energy/variables.h"

namespace ceres {
class Problem;
}  // namespace ceres

namespace lpd::energy {

class FittingTerm {
 public:
  FittingTerm(const Problem& problem, double mu_l, int num_threads = 1)
      : problem_(problem), penalty_(mu_l), num_threads_(num_threads) {}

  // E_fit at `v` (uses v.h and v.l).
  double Evaluate(const Variables& v) const;

  // l_ij = (mu_l / (mu_l + (h_i^T q_j)^2))^2 for all i, j (Eq. 6).
  void UpdateLineProcesses(Variables* v) const;

  // Adds one residual h_i^T q_j per i and j in N(i) u {i}, with loss alpha_i rho_mu_l, on the
  // parameter blocks v->h (rows). `problem` must own its cost and loss functions (the Ceres
  // default) and must not outlive `v`.
  void AddResiduals(Variables* v, ceres::Problem* problem) const;

  // h^T q_j, the algebraic distance of p_j to the plane h.
  double Residual(const Eigen::Vector4d& h, int j) const {
    return h.head<3>().dot(problem_.points[j]) + h[3];
  }

 private:
  const Problem& problem_;
  GemanMcClure penalty_;
  int num_threads_;
};

}  // namespace lpd::energy

#endif  // LPD_ENERGY_FITTING_TERM_H_
