#include "solvers/neighborhood_size.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "energy/problem.h"
#include "solvers/initial_state.h"
#include "solvers/residual_statistics.h"

namespace lpd::solvers {

bool NeighborhoodSizeOptions::IsValid(std::string* error) const {
  std::ostringstream out;
  if (probe_k < 4) {
    out << "probe_k must be >= 4, got " << probe_k;
  } else if (!(radius_in_sigmas > 0.0) || !std::isfinite(radius_in_sigmas)) {
    out << "k_radius_sigmas must be finite and > 0, got " << radius_in_sigmas;
  } else if (min_k < 3 || max_k < min_k) {
    out << "need 3 <= min_k <= max_k, got " << min_k << " and " << max_k;
  } else {
    return true;
  }
  *error = out.str();
  return false;
}

NeighborhoodSize ChooseNeighborhoodSize(const energy::PointList& points,
                                        const NeighborhoodSizeOptions& options,
                                        int num_threads) {
  energy::ProblemOptions probe_options;
  probe_options.k = options.probe_k;
  const energy::Problem probe = energy::BuildProblem(points, probe_options, num_threads);
  const energy::Variables planes =
      InitialState(probe, energy::EnergyParameters(), Initialization::kPlaneFit, num_threads);
  const double k = probe_options.k;
  NeighborhoodSize size;
  size.noise_sigma = RobustFittingResidualScale(probe, planes) * std::sqrt((k + 1) / (k - 2));
  std::vector<double> alpha = probe.alpha;
  const auto middle = alpha.begin() + alpha.size() / 2;
  std::nth_element(alpha.begin(), middle, alpha.end());
  size.spacing = std::sqrt(2.0 * M_PI * *middle / k);
  const double radius_in_spacings = options.radius_in_sigmas * size.noise_sigma / size.spacing;
  const double chosen = M_PI * radius_in_spacings * radius_in_spacings;
  const int largest = std::min<int>(options.max_k, static_cast<int>(points.size()) - 1);
  size.k = static_cast<int>(std::lround(std::clamp(chosen, double(options.min_k),
                                                   double(std::max(options.min_k, largest)))));
  return size;
}

}  // namespace lpd::solvers
