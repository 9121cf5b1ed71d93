#include "energy/coordinate_quantization.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace lpd::energy {
namespace {

constexpr size_t kMaxSampledPoints = size_t{1} << 17;

}  // namespace

double QuantizationNoise(const PointList& points) {
  if (points.size() < 2) return 0.0;
  // An evenly strided subset of at most 2^17 points finds the same steps (neighbouring levels
  // still co-occur) in a few milliseconds.
  const size_t stride = (points.size() + kMaxSampledPoints - 1) / kMaxSampledPoints;
  std::vector<double> values;
  values.reserve(points.size() / stride + 1);
  double steps[3] = {0.0, 0.0, 0.0};
  for (int axis = 0; axis < 3; ++axis) {
    values.clear();
    for (size_t i = 0; i < points.size(); i += stride) values.push_back(points[i][axis]);
    std::sort(values.begin(), values.end());
    double step = std::numeric_limits<double>::infinity();
    for (size_t i = 1; i < values.size(); ++i) {
      const double gap = values[i] - values[i - 1];
      if (gap > 0.0) step = std::min(step, gap);
    }
    if (std::isfinite(step)) steps[axis] = step;
  }
  // Relative to the largest step, so that coordinates near 1e300 or 1e-300 neither overflow
  // nor underflow when squared.
  const double largest = std::max({steps[0], steps[1], steps[2]});
  if (!(largest > 0.0)) return 0.0;
  double sum_of_squares = 0.0;
  for (double step : steps) sum_of_squares += (step / largest) * (step / largest);
  return largest * std::sqrt(sum_of_squares / (3.0 * 12.0));
}

}  // namespace lpd::energy
