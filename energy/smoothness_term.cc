#include "energy/smoothness_term.h"

namespace lpd::energy {

double SmoothnessTerm::Evaluate(const Variables& v) const {
  const int num_pairs = problem_.graph.num_pairs();
  double sum = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : sum) num_threads(num_threads_)
  for (int p = 0; p < num_pairs; ++p) {
    sum += problem_.beta[p] * penalty_.LineProcessCost(SquaredDifference(v, p), v.m[p]);
  }
  return 0.5 * lambda_ * sum;
}

void SmoothnessTerm::UpdateLineProcesses(Variables* v) const {
  const int num_pairs = problem_.graph.num_pairs();
#pragma omp parallel for schedule(static) num_threads(num_threads_)
  for (int p = 0; p < num_pairs; ++p) {
    v->m[p] = penalty_.OptimalLineProcess(SquaredDifference(*v, p));  // Eq. (7)
  }
}

void SmoothnessTerm::UpdateOrientations(Variables* v) const {
  const int num_pairs = problem_.graph.num_pairs();
#pragma omp parallel for schedule(static) num_threads(num_threads_)
  for (int p = 0; p < num_pairs; ++p) {
    const auto& pair = problem_.graph.pairs[p];
    const double tj_squared = v->t.row(pair[1]).squaredNorm();
    if (tj_squared > 0.0) {
      v->s[p] = v->t.row(pair[0]).dot(v->t.row(pair[1])) / tj_squared;  // Eq. (8)
    }
  }
}

}  // namespace lpd::energy
