#include "solvers/thinning.h"

#include <algorithm>
#include <cmath>

#include "solvers/subsample_extension.h"

namespace lpd::solvers {
namespace {

// The subsample is accepted once n_s k is within [kLowestUse, 1] of the budget.
constexpr double kLowestUse = 0.9;
constexpr int kMaxRounds = 8;
constexpr uint64_t kSubsampleSeed = 1;

}  // namespace

Thinning ChooseThinning(const energy::PointList& points, const NeighborhoodSizeOptions& options,
                        int num_threads) {
  const int n = static_cast<int>(points.size());
  Thinning thinning;
  thinning.size = ChooseNeighborhoodSize(points, options, num_threads);
  const double budget = options.max_problem_size;
  double size = static_cast<double>(n) * thinning.size.k;
  if (size <= budget) return thinning;
  // k rises or falls with the density, more slowly than it; stepping the fraction by the
  // square root of the budget's ratio converges either way (and at once when k ~ density).
  double fraction = 1.0;
  for (int round = 0; round < kMaxRounds; ++round) {
    fraction = std::min(1.0, fraction * std::sqrt(budget / size));
    const int count = std::max(options.min_k + 1, static_cast<int>(std::lround(fraction * n)));
    thinning.rows = ChooseSubsample(n, count, kSubsampleSeed);
    energy::PointList sample;
    sample.reserve(count);
    for (int row : thinning.rows) sample.push_back(points[row]);
    thinning.size = ChooseNeighborhoodSize(sample, options, num_threads);
    size = static_cast<double>(count) * thinning.size.k;
    if (size <= budget && size >= kLowestUse * budget) break;
  }
  if (thinning.rows.size() == points.size()) thinning.rows.clear();
  return thinning;
}

}  // namespace lpd::solvers
