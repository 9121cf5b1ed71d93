#include "energy/neighbor_graph.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "energy/nearest_neighbors.h"

namespace lpd::energy {

NeighborGraph BuildNeighborGraph(const PointList& points, int k, int num_threads) {
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
  const NearestNeighbors search(points);
  search.ForEach(
      n, k + 1, num_threads, [&points](int i) { return points[i]; },
      [&graph, k](int i, const int* nearest, const double*, int) {
        // Drop i itself; with duplicate points it need not come first, and it may be missing
        // when more than k duplicates of p_i exist, in which case the farthest one is dropped.
        int* out = graph.neighbors.data() + static_cast<size_t>(i) * k;
        int count = 0;
        for (int a = 0; a <= k && count < k; ++a) {
          if (nearest[a] != i) out[count++] = nearest[a];
        }
      });
  BuildPairs(&graph);
  return graph;
}

void BuildPairs(NeighborGraph* graph) {
  const int n = graph->num_points();
  const int k = graph->k;
  std::vector<uint64_t> keys;
  keys.reserve(static_cast<size_t>(n) * k);
  for (int i = 0; i < n; ++i) {
    const int* nbrs = graph->NeighborsOf(i);
    for (int a = 0; a < k; ++a) {
      const uint64_t lo = std::min(i, nbrs[a]);
      const uint64_t hi = std::max(i, nbrs[a]);
      keys.push_back((lo << 32) | hi);
    }
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());

  graph->pairs.resize(keys.size());
  graph->incident_offsets.assign(n + 1, 0);
  for (size_t p = 0; p < keys.size(); ++p) {
    const int i = static_cast<int>(keys[p] >> 32);
    const int j = static_cast<int>(keys[p] & 0xffffffffu);
    graph->pairs[p] = {i, j};
    ++graph->incident_offsets[i + 1];
    ++graph->incident_offsets[j + 1];
  }
  for (int i = 0; i < n; ++i) graph->incident_offsets[i + 1] += graph->incident_offsets[i];
  graph->incident_pairs.resize(graph->incident_offsets[n]);
  std::vector<int> fill(graph->incident_offsets.begin(), graph->incident_offsets.end() - 1);
  for (size_t p = 0; p < graph->pairs.size(); ++p) {
    graph->incident_pairs[fill[graph->pairs[p][0]]++] = static_cast<int>(p);
    graph->incident_pairs[fill[graph->pairs[p][1]]++] = static_cast<int>(p);
  }
}

}  // namespace lpd::energy
