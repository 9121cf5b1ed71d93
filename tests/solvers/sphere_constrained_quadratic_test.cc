// Eq. (10) / App. A: the secular-equation solution against dense search on S^3, random
// feasible points, the optimality conditions, and the degenerate (hard) cases.
#include "solvers/sphere_constrained_quadratic.h"

#include <random>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

namespace lpd::solvers {
namespace {

double Objective(const Eigen::Matrix4d& a, const Eigen::Vector4d& b, const Eigen::Vector4d& h) {
  return 0.5 * h.dot(a * h) - b.dot(h);
}

Eigen::Vector4d RandomUnit(std::mt19937_64* rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Vector4d x(normal(*rng), normal(*rng), normal(*rng), normal(*rng));
  return x.normalized();
}

// Best of `samples` random unit vectors, then refined by projected gradient descent.
double DenseSearchMinimum(const Eigen::Matrix4d& a, const Eigen::Vector4d& b, int samples,
                          std::mt19937_64* rng) {
  Eigen::Vector4d best = RandomUnit(rng);
  double best_value = Objective(a, b, best);
  for (int s = 0; s < samples; ++s) {
    const Eigen::Vector4d h = RandomUnit(rng);
    const double value = Objective(a, b, h);
    if (value < best_value) {
      best_value = value;
      best = h;
    }
  }
  const double step = 0.5 / (a.cwiseAbs().sum() + b.norm() + 1e-12);
  for (int it = 0; it < 20000; ++it) {
    best = (best - step * (a * best - b)).normalized();
    best_value = std::min(best_value, Objective(a, b, best));
  }
  return best_value;
}

// Checks the global optimality conditions of [hager-2001] Lemma 2.2 and the dense search.
void ExpectGlobalMinimizer(const Eigen::Matrix4d& a, const Eigen::Vector4d& b, uint64_t seed) {
  const SphereQuadraticSolution solution = MinimizeQuadraticOnUnitSphere(a, b);
  const double scale = a.norm() + b.norm() + 1.0;
  ASSERT_NEAR(solution.h.norm(), 1.0, 1e-12);
  EXPECT_LT((a * solution.h - b + solution.multiplier * solution.h).norm(), 1e-9 * scale)
      << "stationarity (A + gamma I) h = b";
  const double lambda_min = Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(a).eigenvalues()[0];
  EXPECT_GE(solution.multiplier, -lambda_min - 1e-9 * scale) << "A + gamma I must be PSD";
  std::mt19937_64 rng(seed);
  const double value = Objective(a, b, solution.h);
  for (int s = 0; s < 20000; ++s) {
    EXPECT_LE(value, Objective(a, b, RandomUnit(&rng)) + 1e-12 * scale);
  }
  EXPECT_NEAR(value, DenseSearchMinimum(a, b, 200000, &rng), 1e-8 * scale);
}

Eigen::Matrix4d RandomSymmetric(std::mt19937_64* rng, bool positive_semidefinite) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = normal(*rng);
  return positive_semidefinite ? Eigen::Matrix4d(m * m.transpose())
                               : Eigen::Matrix4d(m + m.transpose());
}

TEST(SphereConstrainedQuadratic, RandomProblems) {
  std::mt19937_64 rng(12);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int trial = 0; trial < 12; ++trial) {
    const Eigen::Matrix4d a = RandomSymmetric(&rng, trial % 2 == 0);
    const Eigen::Vector4d b = Eigen::Vector4d(normal(rng), normal(rng), normal(rng), normal(rng)) *
                              std::pow(10.0, trial % 4 - 2);
    ExpectGlobalMinimizer(a, b, trial);
  }
}

TEST(SphereConstrainedQuadratic, ZeroLinearTermGivesLowestEigenvector) {
  std::mt19937_64 rng(2);
  const Eigen::Matrix4d a = RandomSymmetric(&rng, true);
  ExpectGlobalMinimizer(a, Eigen::Vector4d::Zero(), 1);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(a);
  const Eigen::Vector4d h = MinimizeQuadraticOnUnitSphere(a, Eigen::Vector4d::Zero()).h;
  EXPECT_NEAR(std::abs(h.dot(eigen.eigenvectors().col(0))), 1.0, 1e-12);
}

TEST(SphereConstrainedQuadratic, HardCaseLinearTermOrthogonalToLowestEigenvector) {
  // A = diag(1, 2, 3, 5), b without a component on e_1 and small enough that
  // sum_i (b_i / (lambda_i - 1))^2 < 1: gamma = -1 and h has an e_1 component.
  const Eigen::Matrix4d a = Eigen::Vector4d(1, 2, 3, 5).asDiagonal();
  const Eigen::Vector4d b(0.0, 0.3, 0.4, 0.5);
  const SphereQuadraticSolution solution = MinimizeQuadraticOnUnitSphere(a, b);
  EXPECT_TRUE(solution.hard_case);
  EXPECT_NEAR(solution.multiplier, -1.0, 1e-12);
  // By hand: h_2 = 0.3 / 1, h_3 = 0.4 / 2, h_4 = 0.5 / 4, h_1 = sqrt(1 - sum of squares).
  EXPECT_NEAR(solution.h[1], 0.3, 1e-12);
  EXPECT_NEAR(solution.h[2], 0.2, 1e-12);
  EXPECT_NEAR(solution.h[3], 0.125, 1e-12);
  EXPECT_NEAR(std::abs(solution.h[0]), std::sqrt(1 - 0.09 - 0.04 - 0.015625), 1e-12);
  ExpectGlobalMinimizer(a, b, 3);
  // The same matrix in a rotated basis, and the near-hard case with a tiny e_1 component.
  std::mt19937_64 rng(9);
  const Eigen::Matrix4d q =
      Eigen::HouseholderQR<Eigen::Matrix4d>(RandomSymmetric(&rng, false)).householderQ();
  ExpectGlobalMinimizer(q * a * q.transpose(), q * b, 4);
  ExpectGlobalMinimizer(a, Eigen::Vector4d(1e-9, 0.3, 0.4, 0.5), 5);
}

TEST(SphereConstrainedQuadratic, RepeatedEigenvalues) {
  ExpectGlobalMinimizer(2.5 * Eigen::Matrix4d::Identity(), Eigen::Vector4d(1, -2, 0.5, 0), 6);
  ExpectGlobalMinimizer(Eigen::Matrix4d::Zero(), Eigen::Vector4d(0, 0, 3, 4), 7);
  ExpectGlobalMinimizer(Eigen::Vector4d(1, 1, 4, 4).asDiagonal().toDenseMatrix(),
                        Eigen::Vector4d(0, 0, 0.5, 0.1), 8);
  // b = 0 and a multiple of the identity: every unit vector is optimal.
  EXPECT_NEAR(MinimizeQuadraticOnUnitSphere(Eigen::Matrix4d::Identity(), Eigen::Vector4d::Zero())
                  .h.norm(),
              1.0, 1e-15);
}

TEST(SphereConstrainedQuadratic, PlaneFittingScaleMatrices) {
  // The matrices of Eq. (10) in practice: alpha (eta I + scatter), alpha ~ 1e-4, eta = 5000.
  std::mt19937_64 rng(10);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int trial = 0; trial < 4; ++trial) {
    Eigen::Matrix4d scatter = Eigen::Matrix4d::Zero();
    for (int j = 0; j < 20; ++j) {
      const Eigen::Vector4d q(0.01 * normal(rng), 0.01 * normal(rng), 1e-4 * normal(rng), 1.0);
      scatter += q * q.transpose();
    }
    const double alpha = 1e-4;
    const Eigen::Matrix4d a = alpha * (5000.0 * Eigen::Matrix4d::Identity() + scatter);
    const Eigen::Vector4d t = RandomUnit(&rng) * (trial == 0 ? 0.0 : 1.0);
    ExpectGlobalMinimizer(a, 5000.0 * alpha * t, 20 + trial);
  }
}

}  // namespace
}  // namespace lpd::solvers
