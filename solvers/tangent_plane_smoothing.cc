#include "solvers/tangent_plane_smoothing.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "energy/row_sum.h"
#include "solvers/parse_by_name.h"

namespace lpd::solvers {

using energy::PlaneField;
using energy::SumOverRows;

const char* PreconditionerName(Preconditioner preconditioner) {
  return preconditioner == Preconditioner::kJacobi ? "jacobi" : "multilevel";
}

bool ParsePreconditioner(const std::string& name, Preconditioner* preconditioner) {
  constexpr Preconditioner kPreconditioners[] = {Preconditioner::kJacobi,
                                                 Preconditioner::kMultilevel};
  return ParseByName(name, kPreconditioners, PreconditionerName, preconditioner);
}

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

TangentPlaneSmoother::TangentPlaneSmoother(const energy::Problem& problem, int num_threads)
    : problem_(problem) {
  const auto& graph = problem.graph;
  const int n = problem.num_points();
  // Row i holds the diagonal and one entry per incident pair. Incident pairs come in
  // increasing partner order, so the row's columns are sorted once the diagonal is placed
  // between the partners below i and those above. AssembleValues writes every value.
  k_.row_offsets.resize(n + 1);
  k_.row_offsets[0] = 0;
  diagonal_entry_.resize(n);
  for (int i = 0; i < n; ++i) {
    const int degree = graph.incident_offsets[i + 1] - graph.incident_offsets[i];
    k_.row_offsets[i + 1] = k_.row_offsets[i] + degree + 1;
  }
  k_.columns.resize(k_.row_offsets[n]);
  k_.values.resize(k_.row_offsets[n]);
  bool sorted = true;
#pragma omp parallel for schedule(static) num_threads(num_threads) reduction(&& : sorted)
  for (int i = 0; i < n; ++i) {
    int entry = k_.row_offsets[i];
    int previous = -1;
    bool diagonal_placed = false;
    for (int e = graph.incident_offsets[i]; e < graph.incident_offsets[i + 1]; ++e) {
      const int partner = Partner(i, e);
      sorted = sorted && partner > previous;
      previous = partner;
      if (!diagonal_placed && partner > i) {
        diagonal_entry_[i] = entry;
        k_.columns[entry++] = i;
        diagonal_placed = true;
      }
      k_.columns[entry++] = partner;
    }
    if (!diagonal_placed) {
      diagonal_entry_[i] = entry;
      k_.columns[entry] = i;
    }
  }
  if (!sorted) {
    throw std::logic_error("incident pairs of a point must come in increasing partner order");
  }
}

int TangentPlaneSmoother::Partner(int i, int incident) const {
  const auto& pair = problem_.graph.pairs[problem_.graph.incident_pairs[incident]];
  return pair[0] == i ? pair[1] : pair[0];
}

void TangentPlaneSmoother::AssembleValues(const energy::EnergyParameters& parameters,
                                          const double* m, const double* s_values,
                                          int num_threads) {
  const auto& graph = problem_.graph;
  const int n = problem_.num_points();
  // Row-parallel: every row writes only its own entries.
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int i = 0; i < n; ++i) {
    double diagonal = parameters.eta * problem_.alpha[i];
    const int first_incident = graph.incident_offsets[i];
    // Row i's entries follow its incident pairs in increasing partner order, with the
    // diagonal placed before the first partner above i: from there on come the pairs
    // {i, j} with i < j, of which i is the first point.
    const int first_above = diagonal_entry_[i] - k_.row_offsets[i];
    for (int e = first_incident; e < graph.incident_offsets[i + 1]; ++e) {
      const int p = graph.incident_pairs[e];
      const double w = parameters.lambda * problem_.beta[p] * (m ? m[p] : 1.0);
      const double s = s_values ? s_values[p] : 1.0;
      const int position = e - first_incident;
      const bool i_is_first = position >= first_above;
      // (e_i - s e_j)(e_i - s e_j)^T: +w at (i,i), +w s^2 at (j,j), -w s off the diagonal.
      diagonal += i_is_first ? w : w * s * s;
      k_.values[k_.row_offsets[i] + (i_is_first ? position + 1 : position)] = -w * s;
    }
    k_.values[diagonal_entry_[i]] = diagonal;
  }
}

Eigen::Array4d TangentPlaneSmoother::Precondition(Preconditioner kind, const double* r,
                                                  int num_threads, double* z) {
  if (kind == Preconditioner::kMultilevel) return multilevel_->Apply(r, num_threads, z);
  const int n = problem_.num_points();
  return SumOverRows(n, num_threads, Eigen::Array4d::Zero().eval(), [&](int i, auto* sum) {
    for (int c = 0; c < 4; ++c) {
      z[4 * i + c] = r[4 * i + c] / k_.values[diagonal_entry_[i]];
      (*sum)[c] += z[4 * i + c] * r[4 * i + c];
    }
  });
}

LinearSolveStats TangentPlaneSmoother::Update(const energy::EnergyParameters& parameters,
                                              const LinearSolverOptions& options,
                                              int num_threads, energy::Variables* v) {
  const int n = problem_.num_points();
  const Preconditioner kind = options.preconditioner;
  if (kind == Preconditioner::kMultilevel && !multilevel_) {
    AssembleValues(parameters, nullptr, nullptr, num_threads);
    multilevel_.emplace(k_, MultilevelOptions{}, num_threads);
  }
  AssembleValues(parameters, v->m.data(), v->s.data(), num_threads);
  if (kind == Preconditioner::kMultilevel) {
    // The near-null space of the smoothness term is the current plane field (t_i = s_ij t_j).
    // Alg. 1's first solve has T = 0 and S = 1, where it is the constant field, which is
    // what a zero field gives. H is no substitute: its orientations are arbitrary until S
    // has aligned them (at 1M points the first solve takes 19 CG iterations with H, 9 with
    // the constant field).
    multilevel_->Update(k_, v->t, num_threads);
  }
  for (auto* work : {&residual_, &preconditioned_, &direction_, &product_}) {
    work->resize(4 * static_cast<size_t>(n));
  }
  // CG on the four columns at once, all arrays row-major n x 4. Sums are deterministic
  // (row_sum.h), so a run is reproducible bit for bit at a fixed thread count.
  double* x = v->t.data();
  double* r = residual_.data();
  double* z = preconditioned_.data();
  double* p = direction_.data();
  double* kp = product_.data();
  const double* h = v->h.data();
  using Array4 = Eigen::Array4d;
  using Array8 = Eigen::Array<double, 8, 1>;

  // r = W - K x; per column the sums of |r|^2 and |W|^2.
  const Array8 start = SumOverRows(n, num_threads, Array8::Zero().eval(), [&](int i, auto* sum) {
    const double weight = parameters.eta * problem_.alpha[i];
    k_.RowTimes(x, i, r + 4 * i);
    for (int c = 0; c < 4; ++c) {
      const double w = weight * h[4 * i + c];
      const double r_c = w - r[4 * i + c];
      r[4 * i + c] = r_c;
      (*sum)[c] += r_c * r_c;
      (*sum)[4 + c] += w * w;
    }
  });
  Array4 residual = start.head<4>().sqrt();
  const Array4 target = options.relative_tolerance * start.tail<4>().sqrt().max(1e-300);
  Array4 rz = Precondition(kind, r, num_threads, z);
  std::copy(z, z + 4 * static_cast<size_t>(n), p);

  LinearSolveStats stats;
  while ((residual > target).any() && stats.iterations < options.max_iterations) {
    const Array4 pkp = SumOverRows(n, num_threads, Array4::Zero().eval(), [&](int i, auto* sum) {
      k_.RowTimes(p, i, kp + 4 * i);
      for (int c = 0; c < 4; ++c) (*sum)[c] += p[4 * i + c] * kp[4 * i + c];
    });
    // Converged columns stop moving (step 0) while the others go on.
    const Array4 step = (residual > target && pkp > 0.0).select(rz / pkp, 0.0);
    if ((step == 0.0).all()) break;
    residual = SumOverRows(n, num_threads, Array4::Zero().eval(), [&](int i, auto* sum) {
      for (int c = 0; c < 4; ++c) {
        x[4 * i + c] += step[c] * p[4 * i + c];
        const double r_c = r[4 * i + c] - step[c] * kp[4 * i + c];
        r[4 * i + c] = r_c;
        (*sum)[c] += r_c * r_c;
      }
    }).sqrt();
    const Array4 rz_next = Precondition(kind, r, num_threads, z);
    const Array4 momentum = (step != 0.0 && rz > 0.0).select(rz_next / rz, 0.0);
#pragma omp parallel for schedule(static) num_threads(num_threads)
    for (int i = 0; i < n; ++i) {
      for (int c = 0; c < 4; ++c) p[4 * i + c] = z[4 * i + c] + momentum[c] * p[4 * i + c];
    }
    rz = rz_next;
    ++stats.iterations;
  }
  stats.relative_residual = (residual / (target / options.relative_tolerance)).maxCoeff();
  return stats;
}

Eigen::SparseMatrix<double, Eigen::RowMajor> TangentPlaneSmoother::SystemMatrix(
    const energy::EnergyParameters& parameters, const energy::Variables& v) {
  AssembleValues(parameters, v.m.data(), v.s.data(), 1);
  const int n = problem_.num_points();
  Eigen::SparseMatrix<double, Eigen::RowMajor> k(n, n);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(k_.values.size());
  for (int i = 0; i < n; ++i) {
    for (int e = k_.row_offsets[i]; e < k_.row_offsets[i + 1]; ++e) {
      entries.emplace_back(i, k_.columns[e], k_.values[e]);
    }
  }
  k.setFromTriplets(entries.begin(), entries.end());
  return k;
}

}  // namespace lpd::solvers
