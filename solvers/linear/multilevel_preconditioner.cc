#include "solvers/linear/multilevel_preconditioner.h"

#include <algorithm>
#include <stdexcept>

#include "energy/row_sum.h"

namespace lpd::solvers {
namespace {

using Row = Eigen::Map<Eigen::Array4d>;
using ConstRow = Eigen::Map<const Eigen::Array4d>;
using Columns4 = Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor>;

}  // namespace

MultilevelPreconditioner::MultilevelPreconditioner(const CompressedRows& k,
                                                   const MultilevelOptions& options,
                                                   int num_threads)
    : options_(options) {
  if (options.aggregate_size < 2 || options.coarsest_size < 1 ||
      !(options.jacobi_damping > 0.0 && options.jacobi_damping < 1.0)) {
    throw std::invalid_argument("multilevel options: aggregate_size >= 2, coarsest_size >= 1 "
                                "and jacobi_damping in (0, 1) are required");
  }
  levels_.emplace_back();
  levels_[0].size = k.num_rows();
  while (levels_.back().size > options.coarsest_size) {
    Level& fine = levels_.back();
    fine.aggregates =
        levels_.size() == 1
            ? RunsKeepingStrongGroups(k, options.aggregate_size, options.strong_coupling)
            : ConsecutiveRuns(fine.size, options.aggregate_size);
    Level coarse;
    coarse.size = fine.aggregates.count;
    coarse.matrix =
        GalerkinPattern(levels_.size() == 1 ? k : fine.matrix, fine.aggregates, num_threads);
    levels_.push_back(std::move(coarse));
  }
  for (size_t l = 0; l < levels_.size(); ++l) {
    Level& level = levels_[l];
    const size_t size = level.size;
    if (l + 1 < levels_.size()) {
      const Aggregates& aggregates = level.aggregates;
      level.to_parent.resize(size);
      level.position.resize(size);
      level.block_offsets.assign(1, 0);
      for (int a = 0; a < aggregates.count; ++a) {
        const int first = aggregates.child_offsets[a];
        const size_t children = aggregates.child_offsets[a + 1] - first;
        level.block_offsets.push_back(level.block_offsets.back() + children * children);
        for (size_t p = 0; p < children; ++p) level.position[aggregates.children[first + p]] = p;
      }
      level.block_inverses.resize(level.block_offsets.back());
    }
    level.solution.resize(4 * size);
    if (l > 0) {
      level.rhs.resize(4 * size);
      level.correction.resize(4 * size);
    }
  }
}

void MultilevelPreconditioner::UpdateProlongations(const energy::PlaneField& field,
                                                   int num_threads) {
  const int n = levels_[0].size;
  // |t_i|, floored at 1e-3 of its mean so that no point drops out of the coarse levels (all
  // 1 for a zero field).
  const double mean_norm =
      energy::SumOverRows(n, num_threads, 0.0, [&](int i, double* sum) {
        *sum += field.row(i).norm();
      }) / n;
  // Each child joins its parent's running oriented sum of the field with the sign that agrees
  // with it (the first child sets the parent's orientation); the sums orient the next level.
  std::vector<double> child_sum, parent_sum;
  for (int l = 0; l + 1 < num_levels(); ++l) {
    Level& level = levels_[l];
    const Aggregates& aggregates = level.aggregates;
    const double* children = l == 0 ? field.data() : child_sum.data();
    parent_sum.resize(4 * static_cast<size_t>(aggregates.count));
#pragma omp parallel for schedule(static) num_threads(ThreadsForRows(level.size, num_threads))
    for (int a = 0; a < aggregates.count; ++a) {
      Eigen::Array4d sum = Eigen::Array4d::Zero();
      for (int k = aggregates.child_offsets[a]; k < aggregates.child_offsets[a + 1]; ++k) {
        const int c = aggregates.children[k];
        const ConstRow child(children + 4 * c);
        const double sign = (sum * child).sum() >= 0.0 ? 1.0 : -1.0;
        sum += sign * child;
        double magnitude = 1.0;
        if (l == 0 && mean_norm > 0.0) magnitude = std::max(field.row(c).norm(), 1e-3 * mean_norm);
        level.to_parent[c] = sign * magnitude;
      }
      Row(parent_sum.data() + 4 * a) = sum;
    }
    child_sum.swap(parent_sum);
  }
}

void MultilevelPreconditioner::Update(const CompressedRows& k, const energy::PlaneField& field,
                                      int num_threads) {
  if (k.num_rows() != levels_[0].size || field.rows() != levels_[0].size) {
    throw std::invalid_argument("multilevel preconditioner: K or the field has the wrong size");
  }
  fine_ = &k;
  UpdateProlongations(field, num_threads);
  for (int l = 0; l < num_levels(); ++l) {
    Level& level = levels_[l];
    const CompressedRows& a = Matrix(l);
    if (l + 1 < num_levels()) {
      GalerkinValues(a, level.to_parent, level.aggregates, num_threads, &levels_[l + 1].matrix);
      UpdateBlockInverses(l, num_threads);
    }
  }
  const Level& coarsest = levels_.back();
  const CompressedRows& bottom = Matrix(num_levels() - 1);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(coarsest.size, coarsest.size);
  for (int a = 0; a < coarsest.size; ++a) {
    for (int e = bottom.row_offsets[a]; e < bottom.row_offsets[a + 1]; ++e) {
      dense(a, bottom.columns[e]) = bottom.values[e];
    }
  }
  coarsest_solver_.compute(dense);
}

void MultilevelPreconditioner::UpdateBlockInverses(int l, int num_threads) {
  Level& level = levels_[l];
  const CompressedRows& a = Matrix(l);
  const Aggregates& aggregates = level.aggregates;
#pragma omp parallel num_threads(ThreadsForRows(level.size, num_threads))
  {
    Eigen::MatrixXd block;
    Eigen::LLT<Eigen::MatrixXd> factor;
#pragma omp for schedule(static)
    for (int g = 0; g < aggregates.count; ++g) {
      const int* children = aggregates.children.data() + aggregates.child_offsets[g];
      const int size = aggregates.child_offsets[g + 1] - aggregates.child_offsets[g];
      const auto [lowest, highest] = std::minmax_element(children, children + size);
      block.setZero(size, size);
      for (int p = 0; p < size; ++p) {
        // The block's columns lie in [lowest, highest], a short stretch of the sorted row
        // (an aggregate gathers nearby points), found by bisection.
        const int i = children[p];
        const int* row_end = a.columns.data() + a.row_offsets[i + 1];
        for (const int* column = std::lower_bound(a.columns.data() + a.row_offsets[i], row_end,
                                                  *lowest);
             column != row_end && *column <= *highest; ++column) {
          const int j = *column;
          if (aggregates.parent[j] == g) {
            block(p, level.position[j]) = a.values[column - a.columns.data()];
          }
        }
      }
      // A principal block of an SPD matrix is SPD.
      factor.compute(block);
      Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          level.block_inverses.data() + level.block_offsets[g], size, size) =
          factor.solve(Eigen::MatrixXd::Identity(size, size));
    }
  }
}

void MultilevelPreconditioner::ApplyBlockInverse(int l, int a, const double* v, bool accumulate,
                                                 double* y) const {
  const Level& level = levels_[l];
  const Aggregates& aggregates = level.aggregates;
  const int first = aggregates.child_offsets[a];
  const int size = aggregates.child_offsets[a + 1] - first;
  const double* inverse = level.block_inverses.data() + level.block_offsets[a];
  const double omega = options_.jacobi_damping;
  for (int p = 0; p < size; ++p) {
    Eigen::Array4d sum = Eigen::Array4d::Zero();
    for (int q = 0; q < size; ++q) sum += inverse[p * size + q] * ConstRow(v + 4 * q);
    Row row(y + 4 * aggregates.children[first + p]);
    if (accumulate) {
      row += omega * sum;
    } else {
      row = omega * sum;
    }
  }
}

void MultilevelPreconditioner::Cycle(int l, const double* b, int num_threads, double* out) {
  Level& level = levels_[l];
  if (l + 1 == num_levels()) {
    Eigen::Map<Columns4>(out, level.size, 4) =
        coarsest_solver_.solve(Eigen::Map<const Columns4>(b, level.size, 4));
    return;
  }
  const CompressedRows& a_l = Matrix(l);
  const Aggregates& aggregates = level.aggregates;
  double* x = level.solution.data();
  const int threads = ThreadsForRows(level.size, num_threads);
  // Pre-smoothing from zero, x = S b, then P^T (b - A x) to the next level.
#pragma omp parallel num_threads(threads)
  {
    std::vector<double> rows(4 * static_cast<size_t>(MaxAggregateSize()));
#pragma omp for schedule(static)
    for (int a = 0; a < aggregates.count; ++a) {
      for (int k = aggregates.child_offsets[a]; k < aggregates.child_offsets[a + 1]; ++k) {
        Row(rows.data() + 4 * (k - aggregates.child_offsets[a])) =
            ConstRow(b + 4 * aggregates.children[k]);
      }
      ApplyBlockInverse(l, a, rows.data(), false, x);
    }
  }
  Level& coarse = levels_[l + 1];
#pragma omp parallel for schedule(static) num_threads(threads)
  for (int a = 0; a < coarse.size; ++a) {
    Eigen::Array4d sum = Eigen::Array4d::Zero();
    Eigen::Array4d product;
    for (int k = aggregates.child_offsets[a]; k < aggregates.child_offsets[a + 1]; ++k) {
      const int i = aggregates.children[k];
      a_l.RowTimes(x, i, product.data());
      sum += level.to_parent[i] * (ConstRow(b + 4 * i) - product);
    }
    Row(coarse.rhs.data() + 4 * a) = sum;
  }
  Cycle(l + 1, coarse.rhs.data(), num_threads, coarse.correction.data());
  // x += P x_coarse, then post-smoothing x + S (b - A x).
  const double* correction = coarse.correction.data();
#pragma omp parallel for schedule(static) num_threads(threads)
  for (int i = 0; i < level.size; ++i) {
    Row(x + 4 * i) += level.to_parent[i] * ConstRow(correction + 4 * aggregates.parent[i]);
  }
#pragma omp parallel num_threads(threads)
  {
    std::vector<double> residual(4 * static_cast<size_t>(MaxAggregateSize()));
#pragma omp for schedule(static)
    for (int a = 0; a < aggregates.count; ++a) {
      // The aggregate's rows of b - A x.
      for (int k = aggregates.child_offsets[a]; k < aggregates.child_offsets[a + 1]; ++k) {
        const int i = aggregates.children[k];
        Row r(residual.data() + 4 * (k - aggregates.child_offsets[a]));
        a_l.RowTimes(x, i, r.data());
        r = ConstRow(b + 4 * i) - r;
        Row(out + 4 * i) = ConstRow(x + 4 * i);
      }
      ApplyBlockInverse(l, a, residual.data(), true, out);
    }
  }
}

Eigen::Array4d MultilevelPreconditioner::Apply(const double* r, int num_threads, double* z) {
  Cycle(0, r, num_threads, z);
  return energy::SumOverRows(levels_[0].size, num_threads, Eigen::Array4d::Zero().eval(),
                             [&](int i, auto* sum) {
    *sum += ConstRow(z + 4 * i) * ConstRow(r + 4 * i);
  });
}

}  // namespace lpd::solvers
