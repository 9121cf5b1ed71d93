#include "energy/fitting_term.h"

namespace lpd::energy {

double FittingTerm::Evaluate(const Variables& v) const {
  const int n = problem_.num_points();
  const int columns = problem_.k() + 1;
  double sum = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : sum) num_threads(num_threads_)
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector4d h = v.h.row(i).transpose();
    double point_sum = 0.0;
    for (int a = 0; a < columns; ++a) {
      const double r = Residual(h, problem_.graph.FittingPoint(i, a));
      point_sum += penalty_.LineProcessCost(r * r, v.l(i, a));
    }
    sum += problem_.alpha[i] * point_sum;
  }
  return 0.5 * sum;
}

void FittingTerm::UpdateLineProcesses(Variables* v) const {
  const int n = problem_.num_points();
  const int columns = problem_.k() + 1;
#pragma omp parallel for schedule(static) num_threads(num_threads_)
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector4d h = v->h.row(i).transpose();
    for (int a = 0; a < columns; ++a) {
      const double r = Residual(h, problem_.graph.FittingPoint(i, a));
      v->l(i, a) = penalty_.OptimalLineProcess(r * r);  // Eq. (6)
    }
  }
}

}  // namespace lpd::energy
