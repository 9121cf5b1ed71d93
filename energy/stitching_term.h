// lpd: the stitching term of Eq. (5), tying the fitted planes H to the smoothed planes T.
//
//   E_stitch = eta/2 sum_i alpha_i |h_i - t_i|^2
#ifndef LPD_ENERGY_STITCHING_TERM_H_
#define LPD_ENERGY_STITCHING_TERM_H_

#include "energy/problem.h"
#include "energy/variables.h"

namespace ceres {
class Problem;
}  // namespace ceres

namespace lpd::energy {

class StitchingTerm {
 public:
  StitchingTerm(const Problem& problem, double eta, int num_threads = 1)
      : problem_(problem), eta_(eta), num_threads_(num_threads) {}

  // E_stitch at `v` (uses v.h and v.t), including the factor eta.
  double Evaluate(const Variables& v) const;

  // Adds one residual sqrt(eta alpha_i) (h_i - t_i) per point, without loss, on the parameter
  // blocks v->h and v->t (rows). `problem` must own its cost functions and not outlive `v`.
  void AddResiduals(Variables* v, ceres::Problem* problem) const;

 private:
  const Problem& problem_;
  double eta_;
  int num_threads_;
};

}  // namespace lpd::energy

#endif  // LPD_ENERGY_STITCHING_TERM_H_
