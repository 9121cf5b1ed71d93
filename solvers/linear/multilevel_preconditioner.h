// lpd: an aggregation multigrid V-cycle, the preconditioner of the T system of Eq. (9).
//
// Jacobi alone needs O(sqrt n) CG iterations on K, because the smoothness term couples
// neighbours much more strongly than the stitching diagonal eta alpha_i holds each plane in
// place: the slow error modes are smooth over the surface. A multigrid cycle removes them on
// coarser levels (the paper used AMG too). Measured on the procedural CAD part at k = 20:
// 10 CG iterations per outer iteration at 25K points and 21 at 1M, where Jacobi needs 94 and
// 234 (docs/performance.md explains what keeps the count growing).
//
// Levels. An aggregate of level l + 1 is a run of `aggregate_size` consecutive nodes of level
// l (solvers/linear/aggregation.h). Solving in Morton order (energy/spatial_order.h) makes these runs
// spatially compact at every level. On the finest level the runs are regrouped so that
// strongly coupled points share one (RunsKeepingStrongGroups): see "Why blocks" below. The
// hierarchy and its sparsity patterns are built once per problem. Coarse matrices are
// Galerkin products A_{l+1} = P_l^T A_l P_l, A_0 = K, refreshed with K's values; the
// coarsest level (at most `coarsest_size` nodes) is solved exactly.
//
// Prolongation. The near-null space of the smoothness term is any plane field with
// t_i = s_ij t_j, and s_ij (Eq. 8) carries both the relative scale and the relative
// orientation of neighbouring planes: about a quarter of the s_ij are negative after the
// first local fit, and |s_ij| ranges over 0.3-5. P_0 therefore maps an aggregate to its
// points with entries sigma_i |t_i| taken from the current field T, and P_l (l >= 1) with
// entries sigma = +-1: the signs orient every child to agree with its siblings' running sum
// of the field, so P_0 ... P_l reproduces T's magnitudes with consistent orientations.
//
// Cycle. One damped block-Jacobi sweep before and after each coarse correction (the same
// sweep, so the cycle is a symmetric operator), exact solve at the bottom:
//   z = S r + (I - S A) (S r + P B_{l+1} P^T (I - A S) r),   S = omega D_B^-1,
// where D_B is A_l restricted to the blocks aggregate x aggregate. Every pair of M adds a
// rank-one 2 x 2 block to K, and P^T keeps that form on every level, so a pair inside an
// aggregate is part of D_B and a pair across two is at most twice its share of D_B:
// A_l <= 2 D_B, and any omega < 1 makes the cycle positive definite, which CG needs. It is,
// for any field and any point order; those only decide how fast CG converges.
//
// Why blocks and not the diagonal: beta_ij ~ 1 / |p_i - p_j|^2 (Eq. 5) has a heavy tail on
// sampled surfaces, and its largest values grow with n (the closest pair gets closer). The
// error where a strongly coupled pair moves together, against its other neighbours, is
// barely damped by point Jacobi (the pair's coupling dominates both diagonals) and a coarse
// node cannot represent it either (it moves the whole aggregate). Solving each aggregate's
// block exactly removes it whenever the pair shares an aggregate, which is why the finest
// aggregates keep strongly coupled points together: among pairs with beta_ij > 20x its
// median, 30% are cut by plain runs of 8. Measured on the CAD part at k = 20, 1M points: 49
// CG iterations with point Jacobi on plain runs, 37 with block Jacobi, 21 with strong pairs
// kept together (global step 4.2 -> 3.3 -> 2.4 s per outer iteration). Whole groups, not
// pairs: in a chain of near-coincident points no single pair dominates every diagonal, and
// gathering the connected groups of strong couplings took the 25K-point count from 13 to 10.

#ifndef LPD_SOLVERS_LINEAR_MULTILEVEL_PRECONDITIONER_H_
#define LPD_SOLVERS_LINEAR_MULTILEVEL_PRECONDITIONER_H_

#include <vector>

#include <Eigen/Dense>

#include "energy/variables.h"
#include "solvers/linear/aggregation.h"
#include "solvers/linear/compressed_rows.h"

namespace lpd::solvers {

struct MultilevelOptions {
  int aggregate_size = 8;       // nodes per aggregate
  int coarsest_size = 64;       // levels are added until one has at most this many nodes
  double jacobi_damping = 0.85;  // omega of the block-Jacobi sweeps, in (0, 1)
  // Points coupled by |k_ij| >= strong_coupling min(k_ii, k_jj) share an aggregate on the
  // finest level (RunsKeepingStrongGroups); above 1, no coupling is strong.
  double strong_coupling = 0.4;
};

class MultilevelPreconditioner {
 public:
  // Builds the levels and their sparsity patterns from K. The finest aggregates read K's
  // values (its strong couplings); the values of later Updates may differ.
  MultilevelPreconditioner(const CompressedRows& k, const MultilevelOptions& options,
                           int num_threads);

  // Refreshes P_l from `field` (the current T; a zero field gives the constant one) and
  // every A_l from K's values. K must keep its pattern and outlive the following Apply calls.
  void Update(const CompressedRows& k, const energy::PlaneField& field, int num_threads);

  // z = B r, one V-cycle, for 4 columns stored row-major (r, z: n x 4). Returns r.z per
  // column, which CG needs next, from the same pass.
  Eigen::Array4d Apply(const double* r, int num_threads, double* z);

  int num_levels() const { return static_cast<int>(levels_.size()); }
  // A_l, for l >= 1 (tests and inspection).
  const CompressedRows& CoarseMatrix(int l) const { return levels_[l].matrix; }

 private:
  struct Level {
    int size = 0;
    CompressedRows matrix;                  // A_l for l >= 1 (level 0 uses K)
    // D_B^-1: aggregate a's block inverse, row-major, in block_inverses from
    // block_offsets[a]; position[i] is node i's place among its aggregate's children. All
    // empty at the coarsest level.
    std::vector<double> block_inverses;
    std::vector<size_t> block_offsets;
    std::vector<int> position;
    Aggregates aggregates;                  // nodes of level l + 1 (none at the coarsest)
    std::vector<double> to_parent;          // P_l's entry of each node (empty at the coarsest)
    std::vector<double> rhs;                // n_l x 4 (l >= 1): P^T of the finer residual
    std::vector<double> solution;           // n_l x 4: the cycle's iterate
    std::vector<double> correction;         // n_l x 4 (l >= 1): the cycle's result
  };

  const CompressedRows& Matrix(int l) const { return l == 0 ? *fine_ : levels_[l].matrix; }
  // P_l's entries from the field and P_0's magnitudes (one pass per level, parallel).
  void UpdateProlongations(const energy::PlaneField& field, int num_threads);
  // D_B^-1 of level l from A_l's values.
  void UpdateBlockInverses(int l, int num_threads);
  // A bound on the nodes of any aggregate (RunsKeepingStrongGroups grows runs to at most 2x).
  int MaxAggregateSize() const { return 2 * options_.aggregate_size; }
  // y = omega D_B^-1 v on aggregate a's rows (v holds just those rows); y is set or, with
  // `accumulate`, added to.
  void ApplyBlockInverse(int l, int a, const double* v, bool accumulate, double* y) const;
  // out = B_l b: one V-cycle from level l down.
  void Cycle(int l, const double* b, int num_threads, double* out);

  MultilevelOptions options_;
  std::vector<Level> levels_;
  const CompressedRows* fine_ = nullptr;
  Eigen::LDLT<Eigen::MatrixXd> coarsest_solver_;
};

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_LINEAR_MULTILEVEL_PRECONDITIONER_H_
