#include "solvers/tangent_plane_smoothing.h"

#include <algorithm>
#include <sstream>

#include "solvers/row_sum.h"

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
  inverse_diagonal_.resize(n);
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
    inverse_diagonal_[i] = 1.0 / diagonal;
  }
}

void TangentPlaneSmoother::RowProduct(const double* x, int i, double* y) const {
  double sum[4] = {0.0, 0.0, 0.0, 0.0};
  for (int e = row_offsets_[i]; e < row_offsets_[i + 1]; ++e) {
    const double value = values_[e];
    const double* x_j = x + 4 * columns_[e];
    for (int c = 0; c < 4; ++c) sum[c] += value * x_j[c];
  }
  for (int c = 0; c < 4; ++c) y[c] = sum[c];
}

LinearSolveStats TangentPlaneSmoother::Update(const energy::EnergyParameters& parameters,
                                              const LinearSolverOptions& options,
                                              int num_threads, energy::Variables* v) {
  AssembleValues(parameters, *v, num_threads);
  const int n = problem_.num_points();
  for (auto* work : {&residual_, &direction_, &product_}) {
    work->resize(4 * static_cast<size_t>(n));
  }
  // CG on the four columns at once, all arrays row-major n x 4, in three parallel passes per
  // iteration: K p; x, r and the dot products; the new direction. The preconditioned
  // residual z = D^-1 r is never stored. Sums are deterministic (row_sum.h), so a run is
  // reproducible bit for bit at a fixed thread count.
  double* x = v->t.data();
  double* r = residual_.data();
  double* p = direction_.data();
  double* kp = product_.data();
  const double* h = v->h.data();
  const double* inverse_diagonal = inverse_diagonal_.data();
  using Array4 = Eigen::Array4d;
  using Array8 = Eigen::Array<double, 8, 1>;
  using Array12 = Eigen::Array<double, 12, 1>;

  // r = W - K x, p = D^-1 r; per column the sums of r.z, |r|^2 and |W|^2.
  const Array12 start =
      SumOverRows(n, num_threads, Array12::Zero().eval(), [&](int i, auto* sum) {
        const double weight = parameters.eta * problem_.alpha[i];
        RowProduct(x, i, r + 4 * i);
        for (int c = 0; c < 4; ++c) {
          const double w = weight * h[4 * i + c];
          const double r_c = w - r[4 * i + c];
          r[4 * i + c] = r_c;
          p[4 * i + c] = inverse_diagonal[i] * r_c;
          (*sum)[c] += inverse_diagonal[i] * r_c * r_c;
          (*sum)[4 + c] += r_c * r_c;
          (*sum)[8 + c] += w * w;
        }
      });
  Array4 rz = start.head<4>();
  Array4 residual = start.segment<4>(4).sqrt();
  const Array4 target = options.relative_tolerance * start.tail<4>().sqrt().max(1e-300);

  LinearSolveStats stats;
  while ((residual > target).any() && stats.iterations < options.max_iterations) {
    const Array4 pkp = SumOverRows(n, num_threads, Array4::Zero().eval(), [&](int i, auto* sum) {
      RowProduct(p, i, kp + 4 * i);
      for (int c = 0; c < 4; ++c) (*sum)[c] += p[4 * i + c] * kp[4 * i + c];
    });
    // Converged columns stop moving (step 0) while the others go on.
    const Array4 step = (residual > target && pkp > 0.0).select(rz / pkp, 0.0);
    if ((step == 0.0).all()) break;
    const Array8 sums = SumOverRows(n, num_threads, Array8::Zero().eval(), [&](int i, auto* sum) {
      for (int c = 0; c < 4; ++c) {
        x[4 * i + c] += step[c] * p[4 * i + c];
        const double r_c = r[4 * i + c] - step[c] * kp[4 * i + c];
        r[4 * i + c] = r_c;
        (*sum)[c] += inverse_diagonal[i] * r_c * r_c;
        (*sum)[4 + c] += r_c * r_c;
      }
    });
    const Array4 momentum = (step != 0.0 && rz > 0.0).select(sums.head<4>() / rz, 0.0);
#pragma omp parallel for schedule(static) num_threads(num_threads)
    for (int i = 0; i < n; ++i) {
      for (int c = 0; c < 4; ++c) {
        p[4 * i + c] = inverse_diagonal[i] * r[4 * i + c] + momentum[c] * p[4 * i + c];
      }
    }
    rz = sums.head<4>();
    residual = sums.tail<4>().sqrt();
    ++stats.iterations;
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
