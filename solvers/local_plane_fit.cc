#include "solvers/local_plane_fit.h"

#include "solvers/sphere_constrained_quadratic.h"

namespace lpd::solvers {

void LocalPlaneSystem(const energy::Problem& problem, const energy::EnergyParameters& parameters,
                      const energy::Variables& v, int i, Eigen::Matrix4d* a,
                      Eigen::Vector4d* b) {
  Eigen::Matrix4d scatter = Eigen::Matrix4d::Zero();
  for (int col = 0; col <= problem.k(); ++col) {
    const int j = problem.graph.FittingPoint(i, col);
    Eigen::Vector4d q;
    q << problem.points[j], 1.0;
    scatter.selfadjointView<Eigen::Lower>().rankUpdate(q, v.l(i, col));
  }
  scatter.triangularView<Eigen::StrictlyUpper>() = scatter.transpose();
  const double alpha = problem.alpha[i];
  *a = alpha * (parameters.eta * Eigen::Matrix4d::Identity() + scatter);
  *b = parameters.eta * alpha * v.t.row(i).transpose();
}

void UpdateLocalPlanes(const energy::Problem& problem, const energy::EnergyParameters& parameters,
                       int num_threads, energy::Variables* v) {
  const int n = problem.num_points();
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int i = 0; i < n; ++i) {
    Eigen::Matrix4d a;
    Eigen::Vector4d b;
    LocalPlaneSystem(problem, parameters, *v, i, &a, &b);
    v->h.row(i) = MinimizeQuadraticOnUnitSphere(a, b).h.transpose();
  }
}

}  // namespace lpd::solvers
