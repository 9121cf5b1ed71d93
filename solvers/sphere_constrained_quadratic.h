// lpd: global minimizer of a quadratic on the unit sphere, Eq. (10) and App. A [hager-2001].
//
//   min_h  1/2 h^T A h - b^T h   s.t. |h| = 1,       A symmetric 4x4 (any sign), b in R^4.
// h* is a global minimizer iff (A + gamma I) h* = b, |h*| = 1 and A + gamma I is positive
// semidefinite, i.e. gamma >= -lambda_1 with lambda_1 the smallest eigenvalue of A
// (Lemma 2.2 of [hager-2001]). With A = U diag(lambda) U^T and g = U^T b, the secular
// equation (12) sum_i g_i^2 / (lambda_i + gamma)^2 = 1 has a unique root in
// gamma > -lambda_1 whenever g has a component along the lowest eigenspace; otherwise
// ("hard case") gamma = -lambda_1 and the lowest eigenvector fills the remaining norm.
#ifndef LPD_SOLVERS_SPHERE_CONSTRAINED_QUADRATIC_H_
#define LPD_SOLVERS_SPHERE_CONSTRAINED_QUADRATIC_H_

#include <Eigen/Core>

namespace lpd::solvers {

struct SphereQuadraticSolution {
  Eigen::Vector4d h = Eigen::Vector4d::Zero();  // the minimizer, |h| = 1
  double multiplier = 0.0;                      // gamma of App. A
  bool hard_case = false;                       // g orthogonal to the lowest eigenspace
};

SphereQuadraticSolution MinimizeQuadraticOnUnitSphere(const Eigen::Matrix4d& a,
                                                      const Eigen::Vector4d& b);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_SPHERE_CONSTRAINED_QUADRATIC_H_
