// lpd: the Geman-McClure function of Eq. (4) as a Ceres loss, so that a joint solve of
// 1/2 sum rho(|f|^2) minimizes Eq. (5) with the line processes eliminated (Eq. 3).
//
//   rho(s)   = s mu / (mu + s)
//   rho'(s)  = (mu / (mu + s))^2        = the optimal line process of Eq. (6)-(7)
//   rho''(s) = -2 mu^2 / (mu + s)^3
// Per-residual weights (alpha_i, lambda beta_ij) are applied with ceres::ScaledLoss.
#ifndef LPD_ENERGY_GEMAN_MCCLURE_LOSS_H_
#define LPD_ENERGY_GEMAN_MCCLURE_LOSS_H_

#include <ceres/loss_function.h>

namespace lpd::energy {

class GemanMcClureLoss final : public ceres::LossFunction {
 public:
  explicit GemanMcClureLoss(double mu) : mu_(mu) {}

  void Evaluate(double s, double rho[3]) const override;

 private:
  double mu_;
};

}  // namespace lpd::energy

#endif  // LPD_ENERGY_GEMAN_MCCLURE_LOSS_H_
