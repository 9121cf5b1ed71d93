#include "solvers/neighborhood_size.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
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
  } else if (min_k < 3) {
    out << "min_k must be >= 3, got " << min_k;
  } else if (max_k < min_k) {
    out << "max_k must be >= " << min_k << " (the smallest k chosen), got " << max_k;
  } else {
    return true;
  }
  *error = out.str();
  return false;
}

NeighborhoodSize ChooseNeighborhoodSize(const energy::PointList& points,
                                        const NeighborhoodSizeOptions& options,
                                        int num_threads) {
  const int n = static_cast<int>(points.size());
  if (n < options.min_k + 1) {
    throw std::invalid_argument("need at least " + std::to_string(options.min_k + 1) +
                                " points to choose k from the data, got " + std::to_string(n) +
                                " (give a smaller --k)");
  }
  energy::ProblemOptions probe_options;
  probe_options.k = std::min(options.probe_k, n - 1);
  const energy::Problem probe = energy::BuildProblem(points, probe_options, num_threads);
  const energy::Variables planes =
      InitialState(probe, energy::EnergyParameters(), Initialization::kPlaneFit, num_threads);
  const double k = probe_options.k;
  NeighborhoodSize size;
  size.noise_sigma = RobustFittingResidualScale(probe, planes) * std::sqrt((k + 1) / (k - 2));
  size.spacing = std::sqrt(2.0 * M_PI * energy::MedianAlpha(probe) / k);
  const double radius_in_spacings = options.radius_in_sigmas * size.noise_sigma / size.spacing;
  const double chosen = M_PI * radius_in_spacings * radius_in_spacings;
  const int largest = std::min<int>(options.max_k, static_cast<int>(points.size()) - 1);
  size.k = static_cast<int>(std::lround(std::clamp(chosen, double(options.min_k),
                                                   double(std::max(options.min_k, largest)))));
  return size;
}

}  // namespace lpd::solvers
