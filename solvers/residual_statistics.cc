#include "solvers/residual_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "energy/fitting_term.h"
#include "energy/plane_projection.h"
#include "energy/smoothness_term.h"
#include "solvers/median.h"

namespace lpd::solvers {

double MaxSquaredFittingResidual(const energy::Problem& problem, const energy::Variables& v,
                                 int num_threads) {
  const energy::FittingTerm fitting(problem, /*mu_l=*/1.0);
  const int n = problem.num_points();
  const int columns = problem.k() + 1;
  double largest = 0.0;
#pragma omp parallel for schedule(static) reduction(max : largest) num_threads(num_threads)
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector4d h = v.h.row(i).transpose();
    for (int a = 0; a < columns; ++a) {
      const double r = fitting.Residual(h, problem.graph.FittingPoint(i, a));
      largest = std::max(largest, r * r);
    }
  }
  return largest;  // max is exact in any order, so the reduction is deterministic
}

double MaxSquaredSmoothnessResidual(const energy::Problem& problem, const energy::Variables& v,
                                    int num_threads) {
  const energy::SmoothnessTerm smoothness(problem, /*lambda=*/1.0, /*mu_m=*/1.0);
  const int num_pairs = problem.graph.num_pairs();
  double largest = 0.0;
#pragma omp parallel for schedule(static) reduction(max : largest) num_threads(num_threads)
  for (int p = 0; p < num_pairs; ++p) {
    largest = std::max(largest, smoothness.SquaredDifference(v, p));
  }
  return largest;
}

double RobustFittingResidualScale(const energy::Problem& problem, const energy::Variables& v) {
  const energy::FittingTerm fitting(problem, /*mu_l=*/1.0);
  const int columns = problem.k() + 1;
  const long total = static_cast<long>(problem.num_points()) * columns;
  constexpr long kMaxSamples = 1 << 20;
  const long stride = (total + kMaxSamples - 1) / kMaxSamples;
  std::vector<double> magnitudes;
  magnitudes.reserve(total / stride + 1);
  for (long index = 0; index < total; index += stride) {
    const int i = static_cast<int>(index / columns);
    const int a = static_cast<int>(index % columns);
    const Eigen::Vector4d h = v.h.row(i).transpose();
    magnitudes.push_back(std::abs(fitting.Residual(h, problem.graph.FittingPoint(i, a))));
  }
  const auto middle = magnitudes.begin() + magnitudes.size() / 2;
  std::nth_element(magnitudes.begin(), middle, magnitudes.end());
  return std::max(kMedianAbsToSigma * *middle, problem.quantization_noise);
}

double FittingNoiseSigma(const energy::Problem& problem, const energy::Variables& v) {
  return std::max(RobustFittingResidualScale(problem, v),
                  kMinMuLNoiseSpacings * energy::SampleSpacing(problem));
}

double NoiseScaledMuL(double noise_sigma, double noise_sigmas) {
  const double scale = noise_sigmas * noise_sigma;
  return std::max(scale * scale, std::numeric_limits<double>::min());
}

double RmsProjectedPointChange(const energy::Problem& problem, const energy::PlaneField& old_t,
                               const energy::PlaneField& new_t, int num_threads) {
  const int n = problem.num_points();
  if (n == 0) return 0.0;
  auto project = [&](const energy::PlaneField& t, int i, energy::Point3* projected) {
    return energy::ProjectOntoPlane(problem.points[i], t.row(i).transpose(), projected);
  };
  std::vector<double> squared_motion(n, 0.0);
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int i = 0; i < n; ++i) {
    energy::Point3 before, after;
    if (project(old_t, i, &before) && project(new_t, i, &after)) {
      squared_motion[i] = (after - before).squaredNorm();
    }
  }
  double sum = 0.0;  // summed in order, so the result does not depend on the threads
  for (double value : squared_motion) sum += value;
  return std::sqrt(sum / n);
}

}  // namespace lpd::solvers
