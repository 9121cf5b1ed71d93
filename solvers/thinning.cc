#include "solvers/thinning.h"

#include <algorithm>
#include <cmath>

#include "solvers/subsample_extension.h"

namespace lpd::solvers {
namespace {

// The subsample is accepted once n_s k is within [kLowestUse, 1] of the budget.
constexpr double kLowestUse = 0.9;
constexpr int kMaxRounds = 8;
// The first step's guess of b (below): k ~ n^0.15-0.2 on 1M points, n^0.4-0.5 on 20-80K.
constexpr double kFirstGrowth = 0.25;
constexpr uint64_t kSubsampleSeed = 1;
// Where the probe cannot read the noise (NoiseUnreadable), the subsample is shrunk by
// kReadableStep per probe until it reads under kReadableRatio spacings (thinning.h).
constexpr double kReadableStep = 0.8;
constexpr int kMaxReadableRounds = 20;

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

double ProblemSize(const Thinning& thinning, int n) {
  const size_t solved = thinning.rows.empty() ? static_cast<size_t>(n) : thinning.rows.size();
  return static_cast<double>(solved) * thinning.size.k;
}

// The probe cannot read the noise (past LastPlaneReadRatio) where thin parts' sides, too
// close to split, make part of the reading too (PlaneReadingWeight under 1): a wider k
// alone, capped at max_k, spans too few noise deviations there.
bool NoiseUnreadable(const NeighborhoodSize& size, const NeighborhoodSizeOptions& options) {
  return options.wide_noise && size.read_sigma > LastPlaneReadRatio() * size.spacing &&
         size.thin_candidate_fraction > kThinShareForPlaneReadings;
}

// The whole cloud where n k meets the budget, else the largest subsample found that does;
// `whole_unreadable`: whether the probe cannot read the whole cloud's noise.
Thinning WithinBudget(const energy::PointList& points, const NeighborhoodSizeOptions& options,
                      int num_threads, bool* whole_unreadable) {
  const int n = static_cast<int>(points.size());
  Thinning whole;
  whole.size = ChooseNeighborhoodSize(points, options, num_threads);
  *whole_unreadable = NoiseUnreadable(whole.size, options);
  const double budget = options.max_problem_size;
  double size = ProblemSize(whole, n);
  int probes = 1;
  if (size <= budget) {
    whole.probes = probes;
    return whole;
  }
  // k grows with the density, but more slowly (k ~ n^b with b about 0.15-0.2 on 1M points:
  // the probe reads the noise lower, relative to the spacing, the denser the cloud), so the
  // size n k ~ n^(1 + b). The first step guesses b (kFirstGrowth); each later step takes b
  // from the last two probes (a secant on log size against log n): the whole cloud and two
  // subsamples on the 1M-point cad_part, against five probes when each step assumed k ~ n. k
  // is an integer, so the search keeps the largest subsample within the budget that it met.
  const double target = 0.5 * (1.0 + kLowestUse) * budget;  // the middle of the window
  double fraction = 1.0;
  double growth = kFirstGrowth;  // b
  double last_fraction = 1.0;
  int last_k = whole.size.k;
  Thinning best;
  for (int round = 0; round < kMaxRounds; ++round) {
    fraction = std::min(1.0, fraction * std::pow(target / size, 1.0 / (1.0 + growth)));
    Thinning candidate = Subsample(points, fraction, options, num_threads);
    ++probes;
    size = ProblemSize(candidate, n);
    if (fraction != last_fraction) {  // k clamped at min_k or max_k: b = 0
      growth = std::clamp(std::log(static_cast<double>(last_k) / candidate.size.k) /
                              std::log(last_fraction / fraction),
                          0.0, 1.0);
    }
    last_fraction = fraction;
    last_k = candidate.size.k;
    if (size <= budget && size > ProblemSize(best, n)) best = std::move(candidate);
    if (size <= budget && size >= kLowestUse * budget) break;
  }
  while (best.rows.empty()) {  // never within the budget yet: shrink until it is
    fraction *= kLowestUse * budget / size;
    Thinning candidate = Subsample(points, fraction, options, num_threads);
    size = ProblemSize(candidate, n);
    ++probes;
    if (size <= budget || static_cast<int>(candidate.rows.size()) <= options.min_k + 1) {
      best = std::move(candidate);
    }
  }
  best.probes = probes;
  return best;
}

}  // namespace

Thinning ChooseThinning(const energy::PointList& points, const NeighborhoodSizeOptions& options,
                        int num_threads) {
  const int n = static_cast<int>(points.size());
  bool unreadable = false;
  Thinning chosen = WithinBudget(points, options, num_threads, &unreadable);
  if (!unreadable) return chosen;
  // Shrunk from the budget's choice, whose probes are cheaper than the whole cloud's: the
  // readable size depends on the surface and the noise, not on n.
  const auto readable = [&](const Thinning& thinning) {
    return thinning.size.read_sigma <= kReadableRatio * thinning.size.spacing &&
           ProblemSize(thinning, n) <= options.max_problem_size;
  };
  const int probes = chosen.probes;
  double fraction = chosen.rows.empty() ? 1.0 : static_cast<double>(chosen.rows.size()) / n;
  for (int round = 1; round <= kMaxReadableRounds && !readable(chosen); ++round) {
    fraction *= kReadableStep;
    chosen = Subsample(points, fraction, options, num_threads);
    chosen.probes = probes + round;
  }
  return chosen;
}

}  // namespace lpd::solvers
