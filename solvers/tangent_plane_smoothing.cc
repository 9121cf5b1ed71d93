#include "solvers/tangent_plane_smoothing.h"

#include <algorithm>
#include <sstream>

namespace lpd::solvers {

using energy::PlaneField;

bool LinearSolverOptions::IsValid(std::string* error) const {
  std::ostringstream out;
  if (!(relative_tolerance > 0.0 && relative_tolerance < 1.0)) {
    out << "linear_tolerance must be in (0, 1), got " << relative_tolerance;
  } else if (max_iterations < 1) {
    out << "max_cg_iterations must be >= 1, got " << max_iterations;
  } else {
    return true;
  }
  *error = out.str();
  return false;
}

TangentPlaneSmoother::TangentPlaneSmoother(const energy::Problem& problem) : problem_(problem) {
  const auto& graph = problem.graph;
  const int n = problem.num_points();
  row_offsets_.resize(n + 1);
  row_offsets_[0] = 0;
  for (int i = 0; i < n; ++i) {
    const int degree = graph.incident_offsets[i + 1] - graph.incident_offsets[i];
    row_offsets_[i + 1] = row_offsets_[i] + degree + 1;
  }
  columns_.resize(row_offsets_[n]);
  values_.assign(row_offsets_[n], 0.0);
  diagonal_entry_.resize(n);
  pair_entry_.resize(2 * static_cast<size_t>(graph.num_pairs()));
  // Row i lists its pairs in increasing partner order (pairs are sorted), with the diagonal
  // placed where it belongs, so columns are sorted within every row.
  std::vector<std::pair<int, int>> row;  // (column, pair or -1 for the diagonal)
  for (int i = 0; i < n; ++i) {
    row.clear();
    row.emplace_back(i, -1);
    for (int e = graph.incident_offsets[i]; e < graph.incident_offsets[i + 1]; ++e) {
      const int p = graph.incident_pairs[e];
      const int partner = graph.pairs[p][0] == i ? graph.pairs[p][1] : graph.pairs[p][0];
      row.emplace_back(partner, p);
    }
    std::sort(row.begin(), row.end());
    for (size_t r = 0; r < row.size(); ++r) {
      const int entry = row_offsets_[i] + static_cast<int>(r);
      columns_[entry] = row[r].first;
      const int p = row[r].second;
      if (p < 0) {
        diagonal_entry_[i] = entry;
      } else {
        pair_entry_[2 * p + (graph.pairs[p][0] == i ? 0 : 1)] = entry;
      }
    }
  }
}

void TangentPlaneSmoother::AssembleValues(const energy::EnergyParameters& parameters,
                                          const energy::Variables& v, int num_threads) {
  const auto& graph = problem_.graph;
  const int n = problem_.num_points();
  // Row-parallel: every row writes only its own entries.
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int i = 0; i < n; ++i) {
    double diagonal = parameters.eta * problem_.alpha[i];
    for (int e = graph.incident_offsets[i]; e < graph.incident_offsets[i + 1]; ++e) {
      const int p = graph.incident_pairs[e];
      const double w = parameters.lambda * problem_.beta[p] * v.m[p];
      const double s = v.s[p];
      const bool i_is_first = graph.pairs[p][0] == i;
      // (e_i - s e_j)(e_i - s e_j)^T: +w at (i,i), +w s^2 at (j,j), -w s off the diagonal.
      diagonal += i_is_first ? w : w * s * s;
      values_[pair_entry_[2 * p + (i_is_first ? 0 : 1)]] = -w * s;
    }
    values_[diagonal_entry_[i]] = diagonal;
  }
}

void TangentPlaneSmoother::Multiply(const PlaneField& x, int num_threads, PlaneField* y) const {
  const int n = problem_.num_points();
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int i = 0; i < n; ++i) {
    Eigen::RowVector4d sum = Eigen::RowVector4d::Zero();
    for (int e = row_offsets_[i]; e < row_offsets_[i + 1]; ++e) {
      sum += values_[e] * x.row(columns_[e]);
    }
    y->row(i) = sum;
  }
}

LinearSolveStats TangentPlaneSmoother::Update(const energy::EnergyParameters& parameters,
                                              const LinearSolverOptions& options,
                                              int num_threads, energy::Variables* v) {
  AssembleValues(parameters, *v, num_threads);
  const int n = problem_.num_points();
  PlaneField w(n, 4);
  Eigen::VectorXd inverse_diagonal(n);
  for (int i = 0; i < n; ++i) {
    w.row(i) = parameters.eta * problem_.alpha[i] * v->h.row(i);
    inverse_diagonal[i] = 1.0 / values_[diagonal_entry_[i]];
  }
  // Preconditioned CG on the four columns at once: one sparse pass per iteration.
  PlaneField& x = v->t;
  PlaneField r(n, 4), z(n, 4), p(n, 4), kp(n, 4);
  Multiply(x, num_threads, &kp);
  r = w - kp;
  const Eigen::Array4d target =
      options.relative_tolerance * w.colwise().norm().transpose().array().max(1e-300);
  z = inverse_diagonal.asDiagonal() * r;
  p = z;
  Eigen::Array4d rz = (r.array() * z.array()).colwise().sum().transpose();
  Eigen::Array4d residual = r.colwise().norm().transpose().array();
  LinearSolveStats stats;
  while ((residual > target).any() && stats.iterations < options.max_iterations) {
    Multiply(p, num_threads, &kp);
    const Eigen::Array4d pkp = (p.array() * kp.array()).colwise().sum().transpose();
    Eigen::Array4d step = Eigen::Array4d::Zero();
    for (int c = 0; c < 4; ++c) {
      if (residual[c] > target[c] && pkp[c] > 0.0) step[c] = rz[c] / pkp[c];
    }
    x += p * step.matrix().asDiagonal();
    r -= kp * step.matrix().asDiagonal();
    z = inverse_diagonal.asDiagonal() * r;
    const Eigen::Array4d rz_next = (r.array() * z.array()).colwise().sum().transpose();
    Eigen::Array4d momentum = Eigen::Array4d::Zero();
    for (int c = 0; c < 4; ++c) {
      if (step[c] != 0.0 && rz[c] > 0.0) momentum[c] = rz_next[c] / rz[c];
    }
    p = z + p * momentum.matrix().asDiagonal();
    rz = rz_next;
    residual = r.colwise().norm().transpose().array();
    ++stats.iterations;
    if ((step == 0.0).all()) break;
  }
  stats.relative_residual = (residual / (target / options.relative_tolerance)).maxCoeff();
  return stats;
}

Eigen::SparseMatrix<double, Eigen::RowMajor> TangentPlaneSmoother::SystemMatrix(
    const energy::EnergyParameters& parameters, const energy::Variables& v) {
  AssembleValues(parameters, v, 1);
  const int n = problem_.num_points();
  Eigen::SparseMatrix<double, Eigen::RowMajor> k(n, n);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(values_.size());
  for (int i = 0; i < n; ++i) {
    for (int e = row_offsets_[i]; e < row_offsets_[i + 1]; ++e) {
      entries.emplace_back(i, columns_[e], values_[e]);
    }
  }
  k.setFromTriplets(entries.begin(), entries.end());
  return k;
}

}  // namespace lpd::solvers
