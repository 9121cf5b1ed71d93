#include "solvers/linear/aggregation.h"

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

namespace {

// Each node's group: the connected components of the couplings with
// |a_ij| >= threshold min(a_ii, a_jj), as the smallest member of the component (union-find).
std::vector<int> StrongGroups(const CompressedRows& a, double threshold) {
  const int n = a.num_rows();
  std::vector<double> diagonal(n, 0.0);
  for (int i = 0; i < n; ++i) {
    for (int e = a.row_offsets[i]; e < a.row_offsets[i + 1]; ++e) {
      if (a.columns[e] == i) diagonal[i] = a.values[e];
    }
  }
  std::vector<int> group(n);
  for (int i = 0; i < n; ++i) group[i] = i;
  auto root = [&](int i) {
    while (group[i] != i) i = group[i] = group[group[i]];
    return i;
  };
  for (int j = 0; j < n; ++j) {
    for (int e = a.row_offsets[j]; e < a.row_offsets[j + 1]; ++e) {
      const int i = a.columns[e];
      if (i < j && std::abs(a.values[e]) >= threshold * std::min(diagonal[i], diagonal[j])) {
        const int root_i = root(i), root_j = root(j);
        group[std::max(root_i, root_j)] = std::min(root_i, root_j);
      }
    }
  }
  for (int i = 0; i < n; ++i) group[i] = root(i);
  return group;
}

}  // namespace

Aggregates RunsKeepingStrongGroups(const CompressedRows& a, int run_length, double threshold) {
  const int n = a.num_rows();
  const std::vector<int> group = StrongGroups(a, threshold);
  // The members of group g (rooted at its smallest member g) are members[offsets[g] ...
  // offsets[g + 1]), in increasing order.
  std::vector<int> offsets(n + 1, 0), members(n);
  for (int i = 0; i < n; ++i) ++offsets[group[i] + 1];
  for (int i = 0; i < n; ++i) offsets[i + 1] += offsets[i];
  std::vector<int> next(offsets.begin(), offsets.end() - 1);
  for (int i = 0; i < n; ++i) members[next[group[i]]++] = i;

  std::vector<int> run(n);
  std::vector<int> run_size((n + run_length - 1) / run_length, 0);
  for (int i = 0; i < n; ++i) ++run_size[run[i] = i / run_length];
  for (int g = 0; g < n; ++g) {
    const int first = offsets[g], last = offsets[g + 1];
    if (last - first < 2 || run[members[first]] == run[members[last - 1]]) continue;
    // The run that holds most members (the first of equals); members come in run order.
    int target = -1, best = 0;
    for (int b = first; b < last;) {
      int e = b;
      while (e < last && run[members[e]] == run[members[b]]) ++e;
      if (e - b > best) {
        best = e - b;
        target = run[members[b]];
      }
      b = e;
    }
    for (int b = first; b < last && run_size[target] < 2 * run_length; ++b) {
      const int i = members[b];
      if (run[i] == target) continue;
      --run_size[run[i]];
      ++run_size[target];
      run[i] = target;
    }
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
