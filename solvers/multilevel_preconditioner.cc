#include "solvers/multilevel_preconditioner.h"

#include <algorithm>

#include "energy/row_sum.h"

namespace lpd::solvers {
namespace {

using Row = Eigen::Map<Eigen::Array4d>;
using ConstRow = Eigen::Map<const Eigen::Array4d>;

}  // namespace

MultilevelPreconditioner::MultilevelPreconditioner(int num_points, int branching,
                                                   int max_levels)
    : branching_(branching) {
  level_sizes_.push_back(num_points);
  while (level_sizes_.back() > 1 && static_cast<int>(level_sizes_.size()) < max_levels) {
    level_sizes_.push_back((level_sizes_.back() + branching - 1) / branching);
  }
  const int levels = num_levels();
  flip_.resize(levels - 1);
  inverse_diagonal_.resize(levels);
  restricted_.resize(levels);
  for (int l = 0; l < levels; ++l) {
    if (l + 1 < levels) flip_[l].assign(level_sizes_[l], 1);
    inverse_diagonal_[l].assign(level_sizes_[l], 0.0);
    if (l > 0) restricted_[l].assign(4 * static_cast<size_t>(level_sizes_[l]), 0.0);
  }
}

void MultilevelPreconditioner::Update(const SymmetricRows& k,
                                      const energy::PlaneField& field) {
  const int levels = num_levels();
  const int n = level_sizes_[0];
  if (levels > 1) {
    // Scales |t_i|, floored at 1e-3 of their mean so that no point drops out of the coarse
    // levels (all 1 for a zero field).
    scale_.resize(n);
    double mean_norm = 0.0;
    for (int i = 0; i < n; ++i) mean_norm += field.row(i).norm() / n;
    for (int i = 0; i < n; ++i) {
      scale_[i] = mean_norm > 0.0 ? std::max(field.row(i).norm(), 1e-3 * mean_norm) : 1.0;
    }
  }
  // Orientations: each child joins its parent's running oriented sum of the field with the
  // sign that agrees with it (the first child sets the parent's orientation).
  std::vector<double> child_sum, parent_sum;
  for (int l = 0; l + 1 < levels; ++l) {
    const double* children = l == 0 ? field.data() : child_sum.data();
    parent_sum.assign(4 * static_cast<size_t>(level_sizes_[l + 1]), 0.0);
    for (int c = 0; c < level_sizes_[l]; ++c) {
      Row parent(parent_sum.data() + 4 * Parent(c));
      const ConstRow child(children + 4 * c);
      const signed char flip = (parent * child).sum() >= 0.0 ? 1 : -1;
      flip_[l][c] = flip;
      parent += flip * child;
    }
    child_sum.swap(parent_sum);
  }
  // D_l = diag(P_l^T K P_l): entry (i, j) of K adds sigma_l(i) sigma_l(j) K_ij to every level
  // at which i and j share an aggregate. Once they share one the sign product stays fixed,
  // so each entry is added once, at the level where i and j meet, and every level then
  // inherits its children's sums.
  // Accumulated in place, then inverted.
  std::vector<std::vector<double>>& diagonal = inverse_diagonal_;
  for (std::vector<double>& level : diagonal) std::fill(level.begin(), level.end(), 0.0);
  for (int i = 0; i < n; ++i) {
    for (int e = k.row_offsets[i]; e < k.row_offsets[i + 1]; ++e) {
      int a = i, b = k.columns[e], l = 0;
      // Diagonal entries: K_ii for Jacobi, |t_i|^2 K_ii from level 1 up.
      if (a == b) {
        diagonal[0][a] += k.values[e];
        if (levels > 1) diagonal[1][Parent(a)] += scale_[a] * scale_[a] * k.values[e];
        continue;
      }
      if (levels == 1) continue;  // Jacobi: off-diagonal entries never share an aggregate
      double sign = scale_[a] * scale_[b];
      while (a != b && l + 1 < levels) {
        sign *= flip_[l][a] * flip_[l][b];
        a = Parent(a);
        b = Parent(b);
        ++l;
      }
      if (a == b) diagonal[l][a] += sign * k.values[e];
    }
  }
  for (int l = 2; l < levels; ++l) {
    for (int c = 0; c < level_sizes_[l - 1]; ++c) diagonal[l][Parent(c)] += diagonal[l - 1][c];
  }
  for (std::vector<double>& level : diagonal) {
    for (double& d : level) d = 1.0 / d;
  }
}

Eigen::Array4d MultilevelPreconditioner::Apply(const double* r, int num_threads, double* z) {
  const int levels = num_levels();
  // Restriction P_l^T r, level by level: a parent sums its children's oriented residuals.
  for (int l = 1; l < levels; ++l) {
    const double* child = l == 1 ? r : restricted_[l - 1].data();
    const int children = level_sizes_[l - 1];
#pragma omp parallel for schedule(static) num_threads(num_threads)
    for (int a = 0; a < level_sizes_[l]; ++a) {
      Eigen::Array4d sum = Eigen::Array4d::Zero();
      const int end = std::min(children, (a + 1) * branching_);
      for (int c = a * branching_; c < end; ++c) {
        sum += (l == 1 ? scale_[c] : 1.0) * flip_[l - 1][c] * ConstRow(child + 4 * c);
      }
      Row(restricted_[l].data() + 4 * a) = sum;
    }
  }
  // Coarse corrections D_l^-1 P_l^T r, summed top-down into the finer levels.
  for (int l = levels - 1; l >= 1; --l) {
    for (int a = 0; a < level_sizes_[l]; ++a) {
      Row correction(restricted_[l].data() + 4 * a);
      correction *= inverse_diagonal_[l][a];
      if (l + 1 < levels) {
        correction += flip_[l][a] * Row(restricted_[l + 1].data() + 4 * Parent(a));
      }
    }
  }
  const int n = level_sizes_[0];
  return energy::SumOverRows(n, num_threads, Eigen::Array4d::Zero().eval(), [&](int i, auto* sum) {
    Eigen::Array4d z_i = inverse_diagonal_[0][i] * ConstRow(r + 4 * i);
    if (levels > 1) z_i += scale_[i] * flip_[0][i] * Row(restricted_[1].data() + 4 * Parent(i));
    Row(z + 4 * i) = z_i;
    *sum += z_i * ConstRow(r + 4 * i);
  });
}

}  // namespace lpd::solvers
