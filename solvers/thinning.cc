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

// The subsample of round(fraction n) points (at least min_k + 1) and its k.
Thinning Subsample(const energy::PointList& points, double fraction,
                   const NeighborhoodSizeOptions& options, int num_threads) {
  const int n = static_cast<int>(points.size());
  const int count = std::max(options.min_k + 1, static_cast<int>(std::lround(fraction * n)));
  Thinning thinning;
  thinning.rows = ChooseSubsample(n, count, kSubsampleSeed);
  energy::PointList sample;
  sample.reserve(count);
  for (int row : thinning.rows) sample.push_back(points[row]);
  thinning.size = ChooseNeighborhoodSize(sample, options, num_threads);
  return thinning;
}

double ProblemSize(const Thinning& thinning) {
  return static_cast<double>(thinning.rows.size()) * thinning.size.k;
}

}  // namespace

Thinning ChooseThinning(const energy::PointList& points, const NeighborhoodSizeOptions& options,
                        int num_threads) {
  const int n = static_cast<int>(points.size());
  Thinning whole;
  whole.size = ChooseNeighborhoodSize(points, options, num_threads);
  const double budget = options.max_problem_size;
  double size = static_cast<double>(n) * whole.size.k;
  if (size <= budget) return whole;
  // k rises or falls with the density, more slowly than it; stepping the fraction by the
  // square root of the ratio to the target converges either way (at once when k ~ density). k is
  // an integer, so the search keeps the largest subsample within the budget that it met.
  const double target = 0.5 * (1.0 + kLowestUse) * budget;  // the middle of the window
  double fraction = 1.0;
  Thinning best;
  for (int round = 0; round < kMaxRounds; ++round) {
    fraction = std::min(1.0, fraction * std::sqrt(target / size));
    Thinning candidate = Subsample(points, fraction, options, num_threads);
    size = ProblemSize(candidate);
    if (size <= budget && size > ProblemSize(best)) best = std::move(candidate);
    if (size <= budget && size >= kLowestUse * budget) break;
  }
  while (best.rows.empty()) {  // never within the budget yet: shrink until it is
    fraction *= kLowestUse * budget / size;
    Thinning candidate = Subsample(points, fraction, options, num_threads);
    size = ProblemSize(candidate);
    if (size <= budget || static_cast<int>(candidate.rows.size()) <= options.min_k + 1) {
      best = std::move(candidate);
    }
  }
  return best;
}

}  // namespace lpd::solvers
