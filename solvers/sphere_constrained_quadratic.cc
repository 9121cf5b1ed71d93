#include "solvers/sphere_constrained_quadratic.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

namespace lpd::solvers {
namespace {

// Eigenvalue gaps below this fraction of the problem scale count as one eigenspace.
constexpr double kEigenGapTolerance = 1e-12;
// A component of g below this fraction of |g| counts as zero (hard-case test).
constexpr double kZeroComponentTolerance = 1e-12;
// Root-finding limits for the secular equation.
constexpr int kMaxSecularIterations = 200;
constexpr double kSecularTolerance = 1e-15;

// phi(sigma) = sum_i g_i^2 / (d_i + sigma)^2 and its derivative, sigma = lambda_1 + gamma.
struct Secular {
  const Eigen::Vector4d& g;
  const Eigen::Vector4d& d;
  double Phi(double sigma) const {
    return (g.array() / (d.array() + sigma)).square().sum();
  }
  double DPhi(double sigma) const {
    return -2.0 * (g.array().square() / (d.array() + sigma).cube()).sum();
  }
};

}  // namespace

SphereQuadraticSolution MinimizeQuadraticOnUnitSphere(const Eigen::Matrix4d& a,
                                                      const Eigen::Vector4d& b) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(a);
  const Eigen::Vector4d& lambda = eigen.eigenvalues();  // increasing
  const Eigen::Matrix4d& u = eigen.eigenvectors();
  const Eigen::Vector4d g = u.transpose() * b;
  const Eigen::Vector4d d = lambda.array() - lambda[0];  // d_i >= 0, d_0 = 0
  const double g_norm = g.norm();
  const double scale = std::max({lambda.cwiseAbs().maxCoeff(), g_norm, 1e-300});

  SphereQuadraticSolution solution;
  if (g_norm <= kZeroComponentTolerance * scale) {
    // b = 0: the minimizer is a lowest eigenvector of A (a plain eigenvalue problem).
    solution.h = u.col(0);
    solution.multiplier = -lambda[0];
    solution.hard_case = true;
    return solution;
  }

  // Lowest eigenspace B = {i : d_i ~ 0} and the part of g inside it.
  const double gap_tolerance = kEigenGapTolerance * scale;
  double g_low_squared = 0.0;
  double phi_outside_at_zero = 0.0;  // sum over i not in B of (g_i / d_i)^2
  for (int i = 0; i < 4; ++i) {
    if (d[i] <= gap_tolerance) {
      g_low_squared += g[i] * g[i];
    } else {
      phi_outside_at_zero += (g[i] / d[i]) * (g[i] / d[i]);
    }
  }

  Eigen::Vector4d z;
  if (std::sqrt(g_low_squared) <= kZeroComponentTolerance * g_norm &&
      phi_outside_at_zero <= 1.0) {
    // Hard case: gamma = -lambda_1; the lowest eigenvector completes the unit norm.
    z.setZero();
    for (int i = 0; i < 4; ++i) {
      if (d[i] > gap_tolerance) z[i] = g[i] / d[i];
    }
    z[0] = std::copysign(std::sqrt(std::max(0.0, 1.0 - phi_outside_at_zero)), g[0]);
    solution.multiplier = -lambda[0];
    solution.hard_case = true;
  } else {
    // Secular equation (12) in sigma = lambda_1 + gamma: phi decreases from +inf (or from
    // phi_outside_at_zero > 1) at sigma = 0 to phi(|g|) <= 1, so the root lies in (0, |g|].
    // Safeguarded Newton on psi(sigma) = 1 / sqrt(phi(sigma)) - 1, which is nearly linear.
    const Secular secular{g, d};
    double lo = 0.0;
    double hi = g_norm;
    double sigma = hi;
    for (int iteration = 0; iteration < kMaxSecularIterations; ++iteration) {
      const double phi = secular.Phi(sigma);
      const double psi = 1.0 / std::sqrt(phi) - 1.0;
      if (std::abs(psi) <= kSecularTolerance) break;
      if (psi > 0.0) {
        hi = sigma;
      } else {
        lo = sigma;
      }
      const double dpsi = -0.5 * secular.DPhi(sigma) / (phi * std::sqrt(phi));
      double next = sigma - psi / dpsi;
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (next == sigma || hi - lo <= kSecularTolerance * hi) break;
      sigma = next;
    }
    z = g.array() / (d.array() + sigma);  // Eq. (11)
    z.normalize();
    solution.multiplier = sigma - lambda[0];
  }
  solution.h = u * z;
  return solution;
}

}  // namespace lpd::solvers
