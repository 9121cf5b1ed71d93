#include "energy/plane_residuals.h"

#include <Eigen/Core>

namespace lpd::energy {
namespace {

using Vector4Map = Eigen::Map<const Eigen::Vector4d>;

Eigen::Map<Eigen::Vector4d> Vector4Out(double* x) { return Eigen::Map<Eigen::Vector4d>(x); }

Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>> Jacobian4x4(double* x) {
  return Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(x);
}

}  // namespace

bool PlaneDistanceResidual::Evaluate(double const* const* parameters, double* residuals,
                                     double** jacobians) const {
  residuals[0] = q_.dot(Vector4Map(parameters[0]));
  if (jacobians != nullptr && jacobians[0] != nullptr) {
    Vector4Out(jacobians[0]) = q_;
  }
  return true;
}

bool PlaneDifferenceResidual::Evaluate(double const* const* parameters, double* residuals,
                                       double** jacobians) const {
  const Vector4Map ti(parameters[0]);
  const Vector4Map tj(parameters[1]);
  const double s = parameters[2][0];
  Vector4Out(residuals) = ti - s * tj;
  if (jacobians == nullptr) return true;
  if (jacobians[0] != nullptr) Jacobian4x4(jacobians[0]).setIdentity();
  if (jacobians[1] != nullptr) Jacobian4x4(jacobians[1]) = -s * Eigen::Matrix4d::Identity();
  if (jacobians[2] != nullptr) Vector4Out(jacobians[2]) = -tj;
  return true;
}

bool AlignedPlaneDifferenceResidual::Evaluate(double const* const* parameters,
                                              double* residuals, double** jacobians) const {
  const Vector4Map ti(parameters[0]);
  const Vector4Map tj(parameters[1]);
  const double tj_squared = tj.squaredNorm();
  if (tj_squared == 0.0) {
    Vector4Out(residuals) = ti;
    if (jacobians == nullptr) return true;
    if (jacobians[0] != nullptr) Jacobian4x4(jacobians[0]).setIdentity();
    if (jacobians[1] != nullptr) Jacobian4x4(jacobians[1]).setZero();
    return true;
  }
  const double s = ti.dot(tj) / tj_squared;  // Eq. (8)
  Vector4Out(residuals) = ti - s * tj;
  if (jacobians == nullptr) return true;
  const Eigen::Vector4d u = tj / tj_squared;
  if (jacobians[0] != nullptr) {
    // df/dt_i = I - t_j t_j^T / |t_j|^2
    Jacobian4x4(jacobians[0]) = Eigen::Matrix4d::Identity() - tj * u.transpose();
  }
  if (jacobians[1] != nullptr) {
    // f = t_i - s t_j with ds/dt_j = (t_i - 2 s t_j) / |t_j|^2:
    // df/dt_j = -s I - t_j (t_i - 2 s t_j)^T / |t_j|^2
    Jacobian4x4(jacobians[1]) =
        -s * Eigen::Matrix4d::Identity() - tj * ((ti - 2.0 * s * tj) / tj_squared).transpose();
  }
  return true;
}

bool PlaneStitchingResidual::Evaluate(double const* const* parameters, double* residuals,
                                      double** jacobians) const {
  Vector4Out(residuals) =
      weight_ * (Vector4Map(parameters[0]) - Vector4Map(parameters[1]));
  if (jacobians == nullptr) return true;
  if (jacobians[0] != nullptr) Jacobian4x4(jacobians[0]) = weight_ * Eigen::Matrix4d::Identity();
  if (jacobians[1] != nullptr) Jacobian4x4(jacobians[1]) = -weight_ * Eigen::Matrix4d::Identity();
  return true;
}

}  // namespace lpd::energy
