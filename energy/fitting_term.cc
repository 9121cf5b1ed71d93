#include "energy/fitting_term.h"

#include <vector>

#include <ceres/loss_function.h>
#include <ceres/problem.h>

#include "energy/geman_mcclure_loss.h"
#include "energy/plane_residuals.h"
#include "energy/row_sum.h"

namespace lpd::energy {

double FittingTerm::Evaluate(const Variables& v) const {
  const int n = problem_.num_points();
  const int columns = problem_.k() + 1;
  const double sum = SumOverRows(n, num_threads_, 0.0, [&](int i, double* total) {
    const Eigen::Vector4d h = v.h.row(i).transpose();
    double point_sum = 0.0;
    for (int a = 0; a < columns; ++a) {
      const double r = Residual(h, problem_.graph.FittingPoint(i, a));
      point_sum += penalty_.LineProcessCost(r * r, v.l(i, a));
    }
    *total += problem_.alpha[i] * point_sum;
  });
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

void FittingTerm::AddResiduals(Variables* v, ceres::Problem* problem) const {
  const int n = problem_.num_points();
  const int columns = problem_.k() + 1;
  // One distance function per data point q_j, shared by every plane that fits it.
  std::vector<PlaneDistanceResidual*> distance(n);
  for (int j = 0; j < n; ++j) distance[j] = new PlaneDistanceResidual(problem_.points[j]);
  for (int i = 0; i < n; ++i) {
    ceres::LossFunction* loss = new ceres::ScaledLoss(new GemanMcClureLoss(penalty_.mu()),
                                                      problem_.alpha[i], ceres::TAKE_OWNERSHIP);
    for (int a = 0; a < columns; ++a) {
      problem->AddResidualBlock(distance[problem_.graph.FittingPoint(i, a)], loss,
                                v->h.data() + 4 * i);
    }
  }
}

}  // namespace lpd::energy
