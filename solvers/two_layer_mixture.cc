#include "solvers/two_layer_mixture.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>
#include <Eigen/LU>

namespace lpd::solvers {
namespace {

// The lower layer's responsibility for height t, r = w N(t; m_0, s^2) / (w N(t; m_0, s^2) +
// (1 - w) N(t; m_1, s^2)), is a logistic function of t: with the Gaussians' common factor
// cancelled, r = 1 / (1 + exp(offset + slope t)), one exponential a height (and no 0 / 0 far
// out in both tails, where it tends to 0 or 1 on the nearer mean's side).
class LowerResponsibility {
 public:
  explicit LowerResponsibility(const TwoLayerMixture& fit) {
    const double scale = 0.5 / (fit.deviation * fit.deviation);
    const double apart = fit.mean[1] - fit.mean[0];
    // (t - m_0)^2 - (t - m_1)^2 = (m_1 - m_0) (2 t - m_0 - m_1)
    slope_ = 2.0 * scale * apart;
    offset_ = std::log((1.0 - fit.lower_weight) / fit.lower_weight) -
              scale * apart * (fit.mean[0] + fit.mean[1]);
  }
  double operator()(double t) const { return 1.0 / (1.0 + std::exp(offset_ + slope_ * t)); }

 private:
  double slope_ = 0.0, offset_ = 0.0;
};

}  // namespace

bool FitTwoLayerMixture(const std::vector<double>& heights, double lower_start,
                        double upper_start, double deviation_start, TwoLayerMixture* fit) {
  if (!(lower_start < upper_start) || !(deviation_start > 0.0)) return false;
  TwoLayerMixture& f = *fit;
  f = TwoLayerMixture();
  f.mean[0] = lower_start;
  f.mean[1] = upper_start;
  f.deviation = deviation_start;
  for (int iteration = 0; iteration < kMaxMixtureIterations; ++iteration) {
    double weight[2] = {0.0, 0.0}, moment[2] = {0.0, 0.0}, square = 0.0;
    const LowerResponsibility responsibility(f);
    for (const double t : heights) {
      const double r = responsibility(t);
      weight[0] += r;
      weight[1] += 1.0 - r;
      moment[0] += r * t;
      moment[1] += (1.0 - r) * t;
      square += r * (t - f.mean[0]) * (t - f.mean[0]) +
                (1.0 - r) * (t - f.mean[1]) * (t - f.mean[1]);
    }
    if (!(weight[0] > 0.0 && weight[1] > 0.0)) return false;
    const double lower = moment[0] / weight[0], upper = moment[1] / weight[1];
    const double step = std::max(std::abs(lower - f.mean[0]), std::abs(upper - f.mean[1]));
    f.mean[0] = lower;
    f.mean[1] = upper;
    f.lower_weight = weight[0] / (weight[0] + weight[1]);
    f.deviation = std::sqrt(square / (weight[0] + weight[1]));
    if (!(f.deviation > 0.0) || !std::isfinite(f.deviation)) return false;
    if (step < kMixtureTolerance * f.deviation) break;
  }
  // The empirical Fisher information of the two means.
  Eigen::Matrix2d information = Eigen::Matrix2d::Zero();
  const double inverse_variance = 1.0 / (f.deviation * f.deviation);
  const LowerResponsibility responsibility(f);
  for (const double t : heights) {
    const double r = responsibility(t);
    const Eigen::Vector2d score(r * (t - f.mean[0]) * inverse_variance,
                                (1.0 - r) * (t - f.mean[1]) * inverse_variance);
    information += score * score.transpose();
  }
  const Eigen::Matrix2d covariance = information.inverse();
  f.mean_variance[0] = covariance(0, 0);
  f.mean_variance[1] = covariance(1, 1);
  return std::isfinite(f.mean[0]) && std::isfinite(f.mean[1]) &&
         f.mean_variance[0] > 0.0 && f.mean_variance[1] > 0.0 &&
         std::isfinite(f.mean_variance[0]) && std::isfinite(f.mean_variance[1]);
}

}  // namespace lpd::solvers
