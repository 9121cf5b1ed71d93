// The multilevel preconditioner against M^-1 = sum_l P_l diag(P_l^T K P_l)^-1 P_l^T built
// densely from its definition, and as a CG preconditioner against Jacobi.
#include "solvers/multilevel_preconditioner.h"

#include <random>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "energy/spatial_order.h"
#include "solvers/alternating_minimizer.h"
#include "solvers/tangent_plane_smoothing.h"
#include "test_problems.h"

namespace lpd::solvers {
namespace {

// A random sparse SPD matrix in full compressed rows (both triangles, sorted columns).
struct RandomSymmetricMatrix {
  Eigen::MatrixXd dense;
  std::vector<int> row_offsets, columns;
  std::vector<double> values;
};

RandomSymmetricMatrix MakeMatrix(int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::bernoulli_distribution keep(0.3);
  RandomSymmetricMatrix m;
  m.dense = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (keep(rng)) m.dense(i, j) = m.dense(j, i) = uniform(rng);
    }
  }
  for (int i = 0; i < n; ++i) m.dense(i, i) = m.dense.row(i).cwiseAbs().sum() + 0.5 + uniform(rng);
  m.row_offsets.push_back(0);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      if (m.dense(i, j) != 0.0) {
        m.columns.push_back(j);
        m.values.push_back(m.dense(i, j));
      }
    }
    m.row_offsets.push_back(static_cast<int>(m.columns.size()));
  }
  return m;
}

// A field of planes all parallel to one direction, t_i = sign_i c_i u: the preconditioner
// must give point i the entry +-sign_i c_i |u| in every coarse column of its aggregates.
energy::PlaneField ParallelField(int n, uint64_t seed, Eigen::VectorXd* entries) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> magnitude(0.2, 3.0);
  std::bernoulli_distribution flip(0.4);
  const Eigen::RowVector4d u(0.3, -0.5, 0.8, 0.1);
  energy::PlaneField field(n, 4);
  entries->resize(n);
  for (int i = 0; i < n; ++i) {
    (*entries)[i] = (flip(rng) ? -1.0 : 1.0) * magnitude(rng);
    field.row(i) = (*entries)[i] * u;
  }
  *entries *= u.norm();
  return field;
}

Eigen::MatrixXd DenseInverse(const RandomSymmetricMatrix& k, const Eigen::VectorXd& entries,
                             int branching, int levels) {
  const int n = static_cast<int>(entries.size());
  Eigen::MatrixXd inverse = k.dense.diagonal().cwiseInverse().asDiagonal();
  int size = 1;
  for (int l = 1; l < levels; ++l) {
    size *= branching;
    for (int first = 0; first < n; first += size) {
      Eigen::VectorXd p = Eigen::VectorXd::Zero(n);
      for (int i = first; i < std::min(n, first + size); ++i) p[i] = entries[i];
      inverse += p * p.transpose() / p.dot(k.dense * p);
    }
  }
  return inverse;
}

TEST(MultilevelPreconditioner, MatchesTheDenseDefinition) {
  for (const auto& [n, branching, max_levels] :
       {std::tuple{8, 8, 3}, std::tuple{37, 3, 4}, std::tuple{64, 4, 8}}) {
    const RandomSymmetricMatrix k = MakeMatrix(n, 10 + n);
    Eigen::VectorXd entries;
    const energy::PlaneField field = ParallelField(n, 20 + n, &entries);
    MultilevelPreconditioner preconditioner(n, branching, max_levels);
    preconditioner.Update({k.row_offsets, k.columns, k.values}, field);
    const Eigen::MatrixXd expected =
        DenseInverse(k, entries, branching, preconditioner.num_levels());

    energy::PlaneField r = energy::PlaneField::Random(n, 4);
    energy::PlaneField z(n, 4);
    const Eigen::Array4d rz = preconditioner.Apply(r.data(), 2, z.data());
    const Eigen::MatrixXd z_expected = expected * Eigen::MatrixXd(r);
    EXPECT_LT((Eigen::MatrixXd(z) - z_expected).norm(), 1e-12 * z_expected.norm()) << n;
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(rz[c], r.col(c).dot(z.col(c)), 1e-12 * rz.abs()[c]);
  }
}

TEST(MultilevelPreconditioner, IsSymmetricPositiveDefiniteForAnyField) {
  const int n = 50;
  const RandomSymmetricMatrix k = MakeMatrix(n, 3);
  const energy::PlaneField field = energy::PlaneField::Random(n, 4);
  MultilevelPreconditioner preconditioner(n, 4, 4);
  preconditioner.Update({k.row_offsets, k.columns, k.values}, field);
  ASSERT_EQ(preconditioner.num_levels(), 4);
  // Column j of M^-1, read off the first of the four right-hand sides.
  Eigen::MatrixXd m_inverse(n, n);
  for (int j = 0; j < n; ++j) {
    energy::PlaneField e = energy::PlaneField::Zero(n, 4);
    e(j, 0) = 1.0;
    energy::PlaneField z(n, 4);
    preconditioner.Apply(e.data(), 1, z.data());
    m_inverse.col(j) = z.col(0);
  }
  EXPECT_LT((m_inverse - m_inverse.transpose()).norm(), 1e-12 * m_inverse.norm());
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m_inverse).eigenvalues().minCoeff(),
            0.0);
}

TEST(MultilevelPreconditioner, NeedsFewerConjugateGradientStepsThanJacobi) {
  // A noisy sphere in Morton order after one outer iteration of Alg. 1, as in a real run.
  energy::PointList points = testing::NoisySphere(20000, 0.005, 4);
  energy::PointList sorted;
  for (int i : energy::MortonOrder(points)) sorted.push_back(points[i]);
  const energy::Problem problem = energy::BuildProblem(sorted, energy::ProblemOptions{}, 2);
  energy::Variables v = energy::InitialVariables(problem);
  AlternatingMinimizer::Options options;
  options.max_iterations = 1;
  options.num_threads = 2;
  AlternatingMinimizer::Minimize(problem, options, &v, nullptr);
  int iterations[2];
  for (Preconditioner kind : {Preconditioner::kJacobi, Preconditioner::kMultilevel}) {
    energy::Variables start = v;
    LinearSolverOptions linear;
    linear.relative_tolerance = 1e-8;
    linear.preconditioner = kind;
    TangentPlaneSmoother smoother(problem);
    const LinearSolveStats stats = smoother.Update(options.energy, linear, 2, &start);
    EXPECT_LE(stats.relative_residual, 1e-8);
    iterations[static_cast<int>(kind)] = stats.iterations;
  }
  EXPECT_LT(iterations[1], 0.8 * iterations[0])
      << "jacobi " << iterations[0] << ", multilevel " << iterations[1];
}

}  // namespace
}  // namespace lpd::solvers
