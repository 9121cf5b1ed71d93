// lpd: the residuals of Eq. (5) as Ceres cost functions with analytic Jacobians.
//
// Ceres minimizes 1/2 sum_r rho_r(|f_r|^2); with the losses set by the terms' AddResiduals
// this is Eq. (5) with L and M at their optimum (Eq. 3):
//   PlaneDistanceResidual       f = h_i^T q_j                        loss alpha_i rho_mu_l
//   PlaneDifferenceResidual     f = t_i - s_ij t_j                   loss lambda beta_ij rho_mu_m
//   AlignedPlaneDifferenceResidual  the same with s_ij at its optimum t_i^T t_j / |t_j|^2
//                               (Eq. 8): f = (I - t_j t_j^T / |t_j|^2) t_i
//   PlaneStitchingResidual      f = sqrt(eta alpha_i) (h_i - t_i)    no loss
// Jacobians are row-major, as Ceres expects.
#ifndef LPD_ENERGY_PLANE_RESIDUALS_H_
#define LPD_ENERGY_PLANE_RESIDUALS_H_

#include <ceres/sized_cost_function.h>
#include <Eigen/Core>

#include "energy/point3.h"

namespace lpd::energy {

// Parameters: h (4). The algebraic distance of data point p to plane h.
class PlaneDistanceResidual final : public ceres::SizedCostFunction<1, 4> {
 public:
  explicit PlaneDistanceResidual(const Point3& p) : q_(p.x(), p.y(), p.z(), 1.0) {}
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  Eigen::Vector4d q_;
};

// Parameters: t_i (4), t_j (4), s_ij (1).
class PlaneDifferenceResidual final : public ceres::SizedCostFunction<4, 4, 4, 1> {
 public:
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;
};

// Parameters: t_i (4), t_j (4). Where t_j = 0 every s_ij is optimal and f = t_i; the
// Jacobian with respect to t_j is then taken as 0 (f is not differentiable there).
class AlignedPlaneDifferenceResidual final : public ceres::SizedCostFunction<4, 4, 4> {
 public:
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;
};

// Parameters: h_i (4), t_i (4).
class PlaneStitchingResidual final : public ceres::SizedCostFunction<4, 4, 4> {
 public:
  explicit PlaneStitchingResidual(double weight) : weight_(weight) {}
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  double weight_;  // sqrt(eta alpha_i)
};

}  // namespace lpd::energy

#endif  // LPD_ENERGY_PLANE_RESIDUALS_H_
