#include "energy/term_balance.h"

#include <algorithm>
#include <vector>

namespace lpd::energy {

double MedianSmoothnessToStitchingRatio(const Problem& problem,
                                        const EnergyParameters& parameters, int num_threads) {
  const int n = problem.num_points();
  if (n == 0) return 0.0;
  std::vector<double> ratio(n);
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int i = 0; i < n; ++i) {
    double smoothness = 0.0;
    for (int e = problem.graph.incident_offsets[i]; e < problem.graph.incident_offsets[i + 1];
         ++e) {
      smoothness += parameters.lambda * problem.beta[problem.graph.incident_pairs[e]];
    }
    ratio[i] = smoothness / (parameters.eta * problem.alpha[i]);
  }
  std::nth_element(ratio.begin(), ratio.begin() + n / 2, ratio.end());
  return ratio[n / 2];
}

}  // namespace lpd::energy
