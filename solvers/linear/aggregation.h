// lpd: coarsening by aggregation, for the multigrid preconditioner of the T system.
//
// An aggregation groups the nodes of a sparse symmetric matrix A into disjoint aggregates;
// with a prolongation P that has one entry p_i per node (row i, column parent(i)), the
// coarse matrix is the Galerkin product
//   (P^T A P)_ab = sum_{parent(i) = a, parent(j) = b} p_i p_j A_ij.
//
// The aggregates used are runs of consecutive nodes: in Morton order (energy/spatial_order.h)
// a run is spatially compact, at every level, and the hierarchy costs almost nothing to
// build. On the finest level the runs give up a few points to keep strongly coupled groups
// together (RunsKeepingStrongGroups). Full strength-based aggregation (three rounds of
// strongest-neighbour matching, after Notay) was measured too: with block-Jacobi sweeps it
// needed more CG iterations at 1M points (25-30 against 21) and, its aggregates being
// scattered in memory, twice the time per iteration.
#ifndef LPD_SOLVERS_LINEAR_AGGREGATION_H_
#define LPD_SOLVERS_LINEAR_AGGREGATION_H_

#include <vector>

#include "solvers/linear/compressed_rows.h"

namespace lpd::solvers {

struct Aggregates {
  int count = 0;
  std::vector<int> parent;         // aggregate of each node
  std::vector<int> child_offsets;  // aggregate a's nodes are children[child_offsets[a] ...
  std::vector<int> children;       // ... child_offsets[a + 1]), in increasing order
};

// Aggregates from a parent map with values in [0, count).
Aggregates AggregatesFromParents(std::vector<int> parent, int count);

// Runs of `run_length` consecutive nodes (the last one may be shorter).
Aggregates ConsecutiveRuns(int num_nodes, int run_length);

// Runs of `run_length` consecutive nodes of A, regrouped so that strongly coupled nodes
// share a run. A coupling is strong if |a_ij| >= threshold min(a_ii, a_jj), that is, if it
// holds that share of the diagonal of one of its two nodes. Each connected group of strong
// couplings that spans several runs gathers in the run holding most of its members (the
// first of equals), as long as that run has fewer than 2 run_length nodes. Empty runs are
// dropped; aggregates keep the order of their runs.
Aggregates RunsKeepingStrongGroups(const CompressedRows& a, int run_length, double threshold);

// The sparsity pattern of P^T A P (values zero).
CompressedRows GalerkinPattern(const CompressedRows& a, const Aggregates& aggregates,
                               int num_threads);

// Fills coarse->values (pattern from GalerkinPattern) with P^T A P for P's entries
// `to_parent` (one per node of A; all 1 when empty).
void GalerkinValues(const CompressedRows& a, const std::vector<double>& to_parent,
                    const Aggregates& aggregates, int num_threads, CompressedRows* coarse);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_LINEAR_AGGREGATION_H_
