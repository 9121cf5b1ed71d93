#include "energy/geman_mcclure_loss.h"

namespace lpd::energy {

void GemanMcClureLoss::Evaluate(double s, double rho[3]) const {
  const double inverse = 1.0 / (mu_ + s);
  const double ratio = mu_ * inverse;  // mu / (mu + s)
  rho[0] = s * ratio;
  rho[1] = ratio * ratio;
  rho[2] = -2.0 * ratio * ratio * inverse;
}

}  // namespace lpd::energy
