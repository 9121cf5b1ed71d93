#include "solvers/aggregation.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace lpd::solvers {

Aggregates AggregatesFromParents(std::vector<int> parent, int count) {
  Aggregates aggregates;
  aggregates.count = count;
  aggregates.parent = std::move(parent);
  aggregates.child_offsets.assign(count + 1, 0);
  for (int p : aggregates.parent) ++aggregates.child_offsets[p + 1];
  for (int a = 0; a < count; ++a) aggregates.child_offsets[a + 1] += aggregates.child_offsets[a];
  aggregates.children.resize(aggregates.parent.size());
  std::vector<int> next(aggregates.child_offsets.begin(), aggregates.child_offsets.end() - 1);
  for (int i = 0; i < static_cast<int>(aggregates.parent.size()); ++i) {
    aggregates.children[next[aggregates.parent[i]]++] = i;
  }
  return aggregates;
}

Aggregates ConsecutiveRuns(int num_nodes, int run_length) {
  std::vector<int> parent(num_nodes);
  for (int i = 0; i < num_nodes; ++i) parent[i] = i / run_length;
  return AggregatesFromParents(std::move(parent), (num_nodes + run_length - 1) / run_length);
}

Aggregates RunsKeepingStrongPairs(const CompressedRows& a, int run_length, double threshold) {
  const int n = a.num_rows();
  std::vector<double> diagonal(n, 0.0);
  for (int i = 0; i < n; ++i) {
    for (int e = a.row_offsets[i]; e < a.row_offsets[i + 1]; ++e) {
      if (a.columns[e] == i) diagonal[i] = a.values[e];
    }
  }
  // Each node's strongest neighbour, if the coupling reaches the threshold.
  std::vector<int> strongest(n, -1);
  for (int j = 0; j < n; ++j) {
    double best = threshold;
    for (int e = a.row_offsets[j]; e < a.row_offsets[j + 1]; ++e) {
      const int i = a.columns[e];
      if (i == j) continue;
      const double strength = std::abs(a.values[e]) / std::sqrt(diagonal[i] * diagonal[j]);
      if (strength >= best) {
        best = strength;
        strongest[j] = i;
      }
    }
  }
  auto wants_to_move = [&](int j) {
    const int i = strongest[j];
    if (i < 0 || i / run_length == j / run_length) return false;
    return !(strongest[i] == j && i > j);  // of a mutual pair, the later node moves
  };
  std::vector<int> run(n);
  std::vector<int> run_size((n + run_length - 1) / run_length, 0);
  for (int j = 0; j < n; ++j) ++run_size[j / run_length];
  for (int j = 0; j < n; ++j) {
    run[j] = j / run_length;
    if (!wants_to_move(j) || wants_to_move(strongest[j])) continue;
    const int target = strongest[j] / run_length;
    if (run_size[target] >= 2 * run_length) continue;
    --run_size[run[j]];
    ++run_size[target];
    run[j] = target;
  }
  // Renumber the runs that kept a node.
  std::vector<int> renumbered(run_size.size(), -1);
  int count = 0;
  for (size_t r = 0; r < run_size.size(); ++r) {
    if (run_size[r] > 0) renumbered[r] = count++;
  }
  for (int& r : run) r = renumbered[r];
  return AggregatesFromParents(std::move(run), count);
}

CompressedRows GalerkinPattern(const CompressedRows& a, const Aggregates& aggregates,
                               int num_threads) {
  std::vector<std::vector<int>> rows(aggregates.count);
#pragma omp parallel for schedule(static) num_threads(ThreadsForRows(a.num_rows(), num_threads))
  for (int c = 0; c < aggregates.count; ++c) {
    std::vector<int>& row = rows[c];
    for (int k = aggregates.child_offsets[c]; k < aggregates.child_offsets[c + 1]; ++k) {
      const int i = aggregates.children[k];
      for (int e = a.row_offsets[i]; e < a.row_offsets[i + 1]; ++e) {
        row.push_back(aggregates.parent[a.columns[e]]);
      }
    }
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
  }
  CompressedRows coarse;
  coarse.row_offsets.assign(aggregates.count + 1, 0);
  for (int c = 0; c < aggregates.count; ++c) {
    coarse.row_offsets[c + 1] = coarse.row_offsets[c] + static_cast<int>(rows[c].size());
  }
  coarse.columns.reserve(coarse.row_offsets.back());
  for (std::vector<int>& row : rows) {
    coarse.columns.insert(coarse.columns.end(), row.begin(), row.end());
    std::vector<int>().swap(row);
  }
  coarse.values.assign(coarse.columns.size(), 0.0);
  return coarse;
}

void GalerkinValues(const CompressedRows& a, const std::vector<double>& to_parent,
                    const Aggregates& aggregates, int num_threads, CompressedRows* coarse) {
  auto p = [&](int i) { return to_parent.empty() ? 1.0 : to_parent[i]; };
#pragma omp parallel num_threads(ThreadsForRows(a.num_rows(), num_threads))
  {
    // slot[b] = entry of column b in the coarse row being assembled.
    std::vector<int> slot(aggregates.count);
#pragma omp for schedule(static)
    for (int c = 0; c < aggregates.count; ++c) {
      for (int e = coarse->row_offsets[c]; e < coarse->row_offsets[c + 1]; ++e) {
        slot[coarse->columns[e]] = e;
        coarse->values[e] = 0.0;
      }
      for (int k = aggregates.child_offsets[c]; k < aggregates.child_offsets[c + 1]; ++k) {
        const int i = aggregates.children[k];
        for (int e = a.row_offsets[i]; e < a.row_offsets[i + 1]; ++e) {
          const int j = a.columns[e];
          coarse->values[slot[aggregates.parent[j]]] += p(i) * p(j) * a.values[e];
        }
      }
    }
  }
}

}  // namespace lpd::solvers
