// lpd: the median of a list of values, as the noise probe and the isolation test use it.
#ifndef LPD_SOLVERS_MEDIAN_H_
#define LPD_SOLVERS_MEDIAN_H_

#include <algorithm>
#include <vector>

namespace lpd::solvers {

// The deviation of Gaussian values over the median of their magnitudes: sigma =
// kMedianAbsToSigma median |x| (1 / Phi^-1(3/4)), robust to a minority of outliers.
constexpr double kMedianAbsToSigma = 1.4826;

// The median of `values` (the upper one for an even count), found by partial sorting:
// `values` is reordered. It must not be empty.
inline double Median(std::vector<double>* values) {
  const auto middle = values->begin() + values->size() / 2;
  std::nth_element(values->begin(), middle, values->end());
  return *middle;
}

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_MEDIAN_H_
