#include "energy/stitching_term.h"

namespace lpd::energy {

double StitchingTerm::Evaluate(const Variables& v) const {
  const int n = problem_.num_points();
  double sum = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : sum) num_threads(num_threads_)
  for (int i = 0; i < n; ++i) {
    sum += problem_.alpha[i] * (v.h.row(i) - v.t.row(i)).squaredNorm();
  }
  return 0.5 * eta_ * sum;
}

}  // namespace lpd::energy
