// lpd: two Gaussian layers of one deviation along a line, fitted to heights by EM.
//
// The heights t_a of the inputs across a thin part are a mixture
//   t ~ w N(m_0, s^2) + (1 - w) N(m_1, s^2),
// one component per side. Expectation-maximization from given starts: each height's
// responsibility r_a = w N(t_a; m_0, s^2) / (w N(t_a; m_0, s^2) + (1 - w) N(t_a; m_1, s^2)),
// then m_0 = sum r_a t_a / sum r_a, m_1 likewise with 1 - r_a, w = mean r_a and s^2 the
// responsibility-weighted mean square about the means. The means' variances come from the
// outer products of the per-height scores (r_a (t_a - m_0), (1 - r_a) (t_a - m_1)) / s^2,
// the empirical Fisher information, which counts what the overlap of the layers costs.
#ifndef LPD_SOLVERS_TWO_LAYER_MIXTURE_H_
#define LPD_SOLVERS_TWO_LAYER_MIXTURE_H_

#include <vector>

namespace lpd::solvers {

constexpr int kMaxMixtureIterations = 50;
// EM stops once neither mean moves by more than this share of the deviation.
constexpr double kMixtureTolerance = 1e-4;

struct TwoLayerMixture {
  double mean[2] = {0.0, 0.0};  // lower, upper
  double deviation = 0.0;
  double lower_weight = 0.5;
  double mean_variance[2] = {0.0, 0.0};
};

// The mixture above fitted to `heights` from the means `lower_start` < `upper_start`, equal
// weights and `deviation_start` > 0; false where a component empties or a figure is not
// finite.
bool FitTwoLayerMixture(const std::vector<double>& heights, double lower_start,
                        double upper_start, double deviation_start, TwoLayerMixture* fit);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_TWO_LAYER_MIXTURE_H_
