#include "energy/stitching_term.h"

#include <cmath>

#include <ceres/problem.h>

#include "energy/plane_residuals.h"
#include "energy/row_sum.h"

namespace lpd::energy {

double StitchingTerm::Evaluate(const Variables& v) const {
  const int n = problem_.num_points();
  const double sum = SumOverRows(n, num_threads_, 0.0, [&](int i, double* total) {
    *total += problem_.alpha[i] * (v.h.row(i) - v.t.row(i)).squaredNorm();
  });
  return 0.5 * eta_ * sum;
}

void StitchingTerm::AddResiduals(Variables* v, ceres::Problem* problem) const {
  const int n = problem_.num_points();
  for (int i = 0; i < n; ++i) {
    problem->AddResidualBlock(new PlaneStitchingResidual(std::sqrt(eta_ * problem_.alpha[i])),
                              nullptr, v->h.data() + 4 * i, v->t.data() + 4 * i);
  }
}

}  // namespace lpd::energy
