// lpd: the Geman-McClure robust function and its line-process penalty, Eq. (3)-(4).
//
//   rho_mu(x)  = x^2 / (1 + x^2 / mu)                       robust function
//   Psi_mu(z)  = mu (sqrt(z) - 1)^2,  z in [0, 1]            line-process penalty
//   z*(x^2)    = (mu / (mu + x^2))^2 = argmin_z z x^2 + Psi_mu(z)    (Eq. 6, 7)
// and by Eq. (3), z* x^2 + Psi_mu(z*) = rho_mu(x). mu is the "selectivity": residuals with
// x^2 well below mu are inliers (z near 1), well above are outliers (z near 0).
// All functions take the squared residual s = x^2 >= 0.
#ifndef LPD_ENERGY_GEMAN_MCCLURE_H_
#define LPD_ENERGY_GEMAN_MCCLURE_H_

#include <cmath>

namespace lpd::energy {

class GemanMcClure {
 public:
  explicit GemanMcClure(double mu) : mu_(mu) {}

  double mu() const { return mu_; }

  // rho_mu as a function of s = x^2 (Eq. 4).
  double Rho(double s) const { return s / (1.0 + s / mu_); }

  // Psi_mu(z) (Eq. 4).
  double Penalty(double z) const {
    const double r = std::sqrt(z) - 1.0;
    return mu_ * r * r;
  }

  // The line process minimizing z s + Psi_mu(z) over [0, 1] (Eq. 6, 7).
  double OptimalLineProcess(double s) const {
    const double r = mu_ / (mu_ + s);
    return r * r;
  }

  // z s + Psi_mu(z): the cost of one residual at a given line process.
  double LineProcessCost(double s, double z) const { return z * s + Penalty(z); }

 private:
  double mu_;
};

}  // namespace lpd::energy

#endif  // LPD_ENERGY_GEMAN_MCCLURE_H_
