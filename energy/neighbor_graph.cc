#include "energy/neighbor_graph.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>

#include "energy/nearest_neighbors.h"
#include "energy/sheet_split.h"

namespace lpd::energy {

namespace {

// p_i followed by the points found near it (nearest first). With duplicate points i need not
// come first in `nearest`, and it may be missing when more duplicates of p_i exist than are
// searched, in which case the farthest one is dropped.
void Members(int i, const int* nearest, int found, int wanted, std::vector<int>* out) {
  out->assign(1, i);
  for (int a = 0; a < found && static_cast<int>(out->size()) < wanted; ++a) {
    if (nearest[a] != i) out->push_back(nearest[a]);
  }
}

// The k nearest of members[1 ..] on p_i's side of `split`, then (if fewer than k) the nearest
// of the other side; the k nearest where the split found no two parallel sides.
void OwnSideNearest(const PointList& points, int i, const SheetSplit& split,
                    const std::vector<int>& members, int k, int* own) {
  if (!(split.separation > 0.0)) {
    std::copy_n(members.begin() + 1, k, own);
    return;
  }
  const int side = split.Side(split.Offset(points[i]));
  int count = 0;
  for (size_t a = 1; a < members.size() && count < k; ++a) {
    if (split.Side(split.Offset(points[members[a]])) == side) own[count++] = members[a];
  }
  for (size_t a = 1; a < members.size() && count < k; ++a) {
    if (split.Side(split.Offset(points[members[a]])) != side) own[count++] = members[a];
  }
}

}  // namespace

NeighborGraph BuildNeighborGraph(const PointList& points, int k, int num_threads,
                                 bool split_sheets, const SplitSearch* searched_before,
                                 ThinRegionGrowth growth, SplitNeighborhood judged_on) {
  if (k < 1) throw std::invalid_argument("k must be at least 1, got " + std::to_string(k));
  const int n = static_cast<int>(points.size());
  if (n < k + 1) {
    throw std::invalid_argument("need at least k+1 = " + std::to_string(k + 1) +
                                " points for k = " + std::to_string(k) + ", got " +
                                std::to_string(n));
  }
  NeighborGraph graph;
  graph.k = k;
  graph.neighbors.resize(static_cast<size_t>(n) * k);
  // A thin point's own side is taken from its 2k + 1 nearest: from the search its split is
  // judged on where that holds them, else from a second search over the thin points only.
  const int candidates = std::min(n, 2 * k + 1);
  const int judged = judged_on == SplitNeighborhood::kCandidates ? candidates : k + 1;
  const int searched = split_sheets ? std::min(n, std::max(judged, kSheetSplitPoints)) : k + 1;
  const bool wide = split_sheets && candidates > searched;
  std::vector<float> separation(split_sheets ? n : 0), within_kurtosis(split_sheets ? n : 0),
      footprint_difference(split_sheets ? n : 0);
  std::vector<SheetSplit> splits(wide ? n : 0);
  // Without a second search, each point's k nearest candidates on its own side, in case its
  // region turns out thin.
  LargeVector<int> own_side(split_sheets && !wide ? static_cast<size_t>(n) * k : 0);
  // The earlier search holds the nearest `searched` first in each row; its splits are
  // those judged here when made over as many points.
  const bool reuse = split_sheets && searched_before != nullptr &&
                     searched_before->searched >= searched && searched_before->num_points() == n;
  const bool reuse_splits = reuse && searched_before->split_points == searched;
  auto visit = [&](int i, const int* nearest, const double*, int found) {
    thread_local std::vector<int> members;
    Members(i, nearest, found, searched, &members);
    std::copy_n(members.begin() + 1, k, graph.neighbors.data() + static_cast<size_t>(i) * k);
    if (!split_sheets) return;
    // The earlier split was over `nearest` as found: the same points in the same order
    // as `members` when p_i came first.
    const int size = static_cast<int>(members.size());
    const SheetSplit split = SplitNearJunction(
        points, members.data(), size,
        reuse_splits && nearest[0] == i ? searched_before->splits[i]
                                        : SplitSheets(points, members.data(), size));
    separation[i] = static_cast<float>(split.separation);
    within_kurtosis[i] = static_cast<float>(split.within_kurtosis);
    footprint_difference[i] = static_cast<float>(split.footprint_difference);
    if (wide) {
      splits[i] = split;
    } else {
      OwnSideNearest(points, i, split, members, k, own_side.data() + static_cast<size_t>(i) * k);
    }
  };
  if (reuse) {
#pragma omp parallel for schedule(static) num_threads(num_threads)
    for (int i = 0; i < n; ++i) visit(i, searched_before->NearestOf(i), nullptr, searched);
  } else {
    const NearestNeighbors search(points);
    search.ForEach(n, searched, num_threads, [&points](int i) { return points[i]; }, visit);
  }
  if (split_sheets) {
    // Where the region around p_i is a thin part (sheet_split.h), N(i) is the k nearest
    // candidates on p_i's own side. The regions are judged on the unsplit N first.
    std::vector<char> is_thin(n, 0), may_grow(n, 0);
    size_t seeds = 0;
#pragma omp parallel for schedule(static) num_threads(num_threads) reduction(+ : seeds)
    for (int i = 0; i < n; ++i) {
      RegionSplits region;
      region.Add(separation[i], within_kurtosis[i], footprint_difference[i]);
      for (int a = 0; a < k; ++a) {
        const int j = graph.NeighborsOf(i)[a];
        region.Add(separation[j], within_kurtosis[j], footprint_difference[j]);
      }
      is_thin[i] = region.TwoSides(kThinRegionSeparation);
      may_grow[i] = region.TwoSides(kThinRegionGrowthSeparation);
      seeds += is_thin[i];
    }
    // Growth, in index order until nothing joins: p_i joins when its region passes the lower
    // bar and a point of its N(i) is thin.
    const bool grow = seeds > 0 && (growth == ThinRegionGrowth::kEverywhere ||
                                    (growth == ThinRegionGrowth::kWhereCommon &&
                                     seeds >= kThinGrowthSeedShare * n));
    for (bool joined = grow; joined;) {
      joined = false;
      for (int i = 0; i < n; ++i) {
        if (is_thin[i] || !may_grow[i]) continue;
        const int* neighbors = graph.NeighborsOf(i);
        is_thin[i] = std::any_of(neighbors, neighbors + k, [&](int j) { return is_thin[j]; });
        joined |= is_thin[i] != 0;
      }
    }
    std::vector<int> thin;
    for (int i = 0; i < n; ++i) {
      if (is_thin[i]) thin.push_back(i);
    }
    if (wide && !thin.empty()) {
      const NearestNeighbors search(points);
      search.ForEach(static_cast<int>(thin.size()), candidates, num_threads,
                     [&](int t) { return points[thin[t]]; },
                     [&](int t, const int* nearest, const double*, int found) {
                       thread_local std::vector<int> members;
                       const int i = thin[t];
                       Members(i, nearest, found, candidates, &members);
                       OwnSideNearest(points, i, splits[i], members, k,
                                      graph.neighbors.data() + static_cast<size_t>(i) * k);
                     });
    } else {
      for (int i : thin) {
        std::copy_n(own_side.data() + static_cast<size_t>(i) * k, k,
                    graph.neighbors.data() + static_cast<size_t>(i) * k);
      }
    }
  }
  BuildPairs(&graph, num_threads);
  return graph;
}

void BuildPairs(NeighborGraph* graph, int num_threads) {
  const int n = graph->num_points();
  const int k = graph->k;
  // The pairs {i, j} in increasing (min, max) order, each once: the larger indices are
  // bucketed by the smaller one, and each bucket is sorted on its own (so the order in which
  // the threads fill a bucket does not matter).
  std::vector<int> bucket_size(n, 0);
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int i = 0; i < n; ++i) {
    const int* nbrs = graph->NeighborsOf(i);
    for (int a = 0; a < k; ++a) {
#pragma omp atomic
      ++bucket_size[std::min(i, nbrs[a])];
    }
  }
  std::vector<size_t> bucket_offsets(static_cast<size_t>(n) + 1, 0);
  for (int i = 0; i < n; ++i) bucket_offsets[i + 1] = bucket_offsets[i] + bucket_size[i];
  LargeVector<int> larger(bucket_offsets[n]);
  std::vector<size_t> bucket_fill(bucket_offsets.begin(), bucket_offsets.end() - 1);
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int i = 0; i < n; ++i) {
    const int* nbrs = graph->NeighborsOf(i);
    for (int a = 0; a < k; ++a) {
      size_t slot;
#pragma omp atomic capture
      slot = bucket_fill[std::min(i, nbrs[a])]++;
      larger[slot] = std::max(i, nbrs[a]);
    }
  }
  // distinct[i]: the pairs {i, j} with j > i; below_count[j]: the pairs {i, j} with i < j.
  std::vector<int> distinct(n), below_count(n, 0);
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int i = 0; i < n; ++i) {
    const auto first = larger.begin() + bucket_offsets[i];
    std::sort(first, larger.begin() + bucket_offsets[i + 1]);
    distinct[i] = static_cast<int>(
        std::unique(first, larger.begin() + bucket_offsets[i + 1]) - first);
    for (int b = 0; b < distinct[i]; ++b) {
#pragma omp atomic
      ++below_count[first[b]];
    }
  }
  std::vector<size_t> pair_offsets(static_cast<size_t>(n) + 1, 0);
  graph->incident_offsets.assign(n + 1, 0);
  for (int i = 0; i < n; ++i) {
    pair_offsets[i + 1] = pair_offsets[i] + distinct[i];
    graph->incident_offsets[i + 1] = graph->incident_offsets[i] + below_count[i] + distinct[i];
  }
  graph->pairs.resize(pair_offsets[n]);
  graph->incident_pairs.resize(graph->incident_offsets[n]);
  // Point x's incident pairs in increasing pair order: first the pairs {a, x} with a < x
  // (filled through a, then sorted), then its own pairs {x, b}.
  std::vector<int> below_fill(graph->incident_offsets.begin(), graph->incident_offsets.end() - 1);
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int i = 0; i < n; ++i) {
    for (int b = 0; b < distinct[i]; ++b) {
      const int p = static_cast<int>(pair_offsets[i]) + b;
      const int j = larger[bucket_offsets[i] + b];
      graph->pairs[p] = {i, j};
      int slot;
#pragma omp atomic capture
      slot = below_fill[j]++;
      graph->incident_pairs[slot] = p;
      graph->incident_pairs[graph->incident_offsets[i] + below_count[i] + b] = p;
    }
  }
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int i = 0; i < n; ++i) {
    int* first = graph->incident_pairs.data() + graph->incident_offsets[i];
    std::sort(first, first + below_count[i]);
  }
}

}  // namespace lpd::energy
