#include "energy/smoothness_term.h"

#include <ceres/loss_function.h>
#include <ceres/problem.h>

#include "energy/geman_mcclure_loss.h"
#include "energy/plane_residuals.h"
#include "energy/row_sum.h"

namespace lpd::energy {

double SmoothnessTerm::Evaluate(const Variables& v) const {
  const int num_pairs = problem_.graph.num_pairs();
  const double sum = SumOverRows(num_pairs, num_threads_, 0.0, [&](int p, double* total) {
    *total += problem_.beta[p] * penalty_.LineProcessCost(SquaredDifference(v, p), v.m[p]);
  });
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

void SmoothnessTerm::AddResiduals(Variables* v, bool optimize_orientations,
                                  ceres::Problem* problem) const {
  const int num_pairs = problem_.graph.num_pairs();
  // The residual functions hold no data, so one object serves every pair.
  ceres::CostFunction* difference = optimize_orientations
                                        ? static_cast<ceres::CostFunction*>(new PlaneDifferenceResidual)
                                        : new AlignedPlaneDifferenceResidual;
  for (int p = 0; p < num_pairs; ++p) {
    const auto& pair = problem_.graph.pairs[p];
    ceres::LossFunction* loss = new ceres::ScaledLoss(
        new GemanMcClureLoss(penalty_.mu()), lambda_ * problem_.beta[p], ceres::TAKE_OWNERSHIP);
    double* ti = v->t.data() + 4 * pair[0];
    double* tj = v->t.data() + 4 * pair[1];
    if (optimize_orientations) {
      problem->AddResidualBlock(difference, loss, ti, tj, v->s.data() + p);
    } else {
      problem->AddResidualBlock(difference, loss, ti, tj);
    }
  }
}

}  // namespace lpd::energy
