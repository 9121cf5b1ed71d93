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

// A mixture's means, lower weight and deviation as one vector, the lengths in units of `unit`
// (the starting deviation), so that the extrapolation below weighs them alike.
using MixtureVector = Eigen::Vector4d;

MixtureVector ToVector(const TwoLayerMixture& f, double unit) {
  return MixtureVector(f.mean[0] / unit, f.mean[1] / unit, f.lower_weight, f.deviation / unit);
}

TwoLayerMixture FromVector(const MixtureVector& v, double unit) {
  TwoLayerMixture f;
  f.mean[0] = v[0] * unit;
  f.mean[1] = v[1] * unit;
  f.lower_weight = v[2];
  f.deviation = v[3] * unit;
  return f;
}

// Whether the responsibilities of `f` are defined: a weight strictly between 0 and 1 and a
// positive, finite deviation.
bool Usable(const TwoLayerMixture& f) {
  return f.lower_weight > 0.0 && f.lower_weight < 1.0 && f.deviation > 0.0 &&
         std::isfinite(f.deviation) && std::isfinite(f.mean[0]) && std::isfinite(f.mean[1]);
}

// One EM step from `f`; false where a component empties or the deviation is not finite.
bool EmStep(const std::vector<double>& heights, const TwoLayerMixture& f,
            TwoLayerMixture* next) {
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
  *next = TwoLayerMixture();
  next->mean[0] = moment[0] / weight[0];
  next->mean[1] = moment[1] / weight[1];
  next->lower_weight = weight[0] / (weight[0] + weight[1]);
  next->deviation = std::sqrt(square / (weight[0] + weight[1]));
  return next->deviation > 0.0 && std::isfinite(next->deviation);
}

// Whether the step from `from` to `to` moved neither mean by kMixtureTolerance of `to`'s
// deviation or more.
bool Settled(const TwoLayerMixture& from, const TwoLayerMixture& to) {
  const double step =
      std::max(std::abs(to.mean[0] - from.mean[0]), std::abs(to.mean[1] - from.mean[1]));
  return step < kMixtureTolerance * to.deviation;
}

}  // namespace

bool FitTwoLayerMixture(const std::vector<double>& heights, double lower_start,
                        double upper_start, double deviation_start, TwoLayerMixture* fit) {
  if (!(lower_start < upper_start) || !(deviation_start > 0.0)) return false;
  TwoLayerMixture& f = *fit;
  f = TwoLayerMixture();
  f.mean[0] = lower_start;
  f.mean[1] = upper_start;
  f.deviation = deviation_start;
  // SQUAREM (the squared extrapolation of Varadhan and Roland, 2008): from theta_0, two EM
  // steps give theta_1 and theta_2, r = theta_1 - theta_0, v = theta_2 - theta_1 - r, and the
  // extrapolated theta_0 - 2 a r + a^2 v with a = -|r| / |v|, bounded to [-reach, -1] (a = -1
  // is theta_2, plain EM) and pulled towards -1 where it leaves the weight or deviation
  // undefined; one EM step from there closes the cycle. Where the layers overlap EM creeps
  // (hundreds of steps to the tolerance), and the cycle reaches the same fixed point in a few.
  const double unit = deviation_start;
  double reach = 1.0;
  int steps = 0;
  while (steps < kMaxMixtureIterations) {
    TwoLayerMixture first, second;
    if (!EmStep(heights, f, &first)) return false;
    ++steps;
    if (Settled(f, first) || steps == kMaxMixtureIterations) {
      f = first;
      break;
    }
    if (!EmStep(heights, first, &second)) return false;
    ++steps;
    if (Settled(first, second)) {
      f = second;
      break;
    }
    const MixtureVector start = ToVector(f, unit);
    const MixtureVector r = ToVector(first, unit) - start;
    const MixtureVector v = ToVector(second, unit) - ToVector(first, unit) - r;
    auto extrapolate = [&](double a) { return FromVector(start - 2.0 * a * r + a * a * v, unit); };
    double alpha = v.norm() > 0.0 ? -r.norm() / v.norm() : -1.0;
    alpha = std::clamp(alpha, -reach, -1.0);
    if (alpha == -reach) reach *= 4.0;
    TwoLayerMixture extrapolated = extrapolate(alpha);
    while (!Usable(extrapolated) && alpha < -1.0) {
      alpha = std::min(-1.0, 0.5 * (alpha - 1.0));
      extrapolated = extrapolate(alpha);
    }
    if (!Usable(extrapolated)) extrapolated = second;
    if (steps == kMaxMixtureIterations) {
      f = extrapolated;
      break;
    }
    TwoLayerMixture closed;
    if (!EmStep(heights, extrapolated, &closed)) return false;
    ++steps;
    const bool settled = Settled(extrapolated, closed);
    f = closed;
    if (settled) break;
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
