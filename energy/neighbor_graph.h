// lpd: the k-nearest-neighbour sets N(i) and the symmetric pair set M of Sec. 3.1.
//
// N(i) holds the k nearest samples of point i, excluding i itself (Euclidean distance, ties
// broken by the k-d tree). M holds every unordered pair {i, j} with i in N(j) or j in N(i)
// exactly once, stored as (i, j) with i < j; the smoothness term of Eq. (5) uses that order:
// || t_i - s_ij t_j ||^2. Everything is kept in flat arrays built once.
#ifndef LPD_ENERGY_NEIGHBOR_GRAPH_H_
#define LPD_ENERGY_NEIGHBOR_GRAPH_H_

#include <array>
#include <cstdint>
#include <vector>

#include "energy/point3.h"
#include "energy/split_search.h"
#include "energy/large_vector.h"

namespace lpd::energy {

struct NeighborGraph {
  int k = 0;
  // N(i) = neighbors[i * k, (i + 1) * k), sorted by increasing distance.
  LargeVector<int> neighbors;
  // M: pairs[p] = {i, j}, i < j, sorted lexicographically.
  LargeVector<std::array<int, 2>> pairs;
  // Pairs incident to point i: incident_pairs[incident_offsets[i], incident_offsets[i + 1]),
  // in increasing order of the partner point (a consequence of the pairs' order).
  std::vector<int> incident_offsets;
  LargeVector<int> incident_pairs;

  int num_points() const { return k > 0 ? static_cast<int>(neighbors.size()) / k : 0; }
  int num_pairs() const { return static_cast<int>(pairs.size()); }
  const int* NeighborsOf(int i) const { return neighbors.data() + static_cast<size_t>(i) * k; }
  // The data point of column `column` of N(i) u {i}: i itself for column 0, else the
  // (column - 1)-th neighbour (the layout of the fitting line processes L, see Variables).
  int FittingPoint(int i, int column) const {
    return column == 0 ? i : NeighborsOf(i)[column - 1];
  }
};

// Where the thin regions of a split graph grow through their neighbours whose regions pass
// kThinRegionGrowthSeparation (sheet_split.h): nowhere, where the split regions are
// kThinGrowthSeedShare of the points or more, or wherever there is one.
enum class ThinRegionGrowth { kNone, kWhereCommon, kEverywhere };

// The neighbourhood each point's split is judged on (sheet_split.h): its 2k + 1 nearest, the
// candidates its own side is taken from (at least kSheetSplitPoints); or kSheetSplitPoints
// (k + 1 if more), the thin points' 2k + 1 candidates then found in a second search over them
// alone and told apart by that split.
enum class SplitNeighborhood { kCandidates, kSplitPoints };

// Builds N and M for `points` with a k-d tree (nanoflann), using `num_threads` threads.
// With `split_sheets`, N(i) is the k nearest of the 2k nearest on p_i's own side where they
// lie on two sheets of a thin part (sheet_split.h), so that a fit does not average the two
// sides, the thin regions grown as `growth` says and the splits judged on `judged_on`.
// `searched`, when given, must come from a search over these same points; where it searched
// as many points as the split needs, the graph takes its lists instead of searching again,
// and its splits where they were made over as many points (same result).
// Requires points.size() >= k + 1 and k >= 1; throws std::invalid_argument otherwise.
NeighborGraph BuildNeighborGraph(const PointList& points, int k, int num_threads,
                                 bool split_sheets = false,
                                 const SplitSearch* searched = nullptr,
                                 ThinRegionGrowth growth = ThinRegionGrowth::kWhereCommon,
                                 SplitNeighborhood judged_on = SplitNeighborhood::kCandidates);

// Builds M and the incidence lists from already filled `graph.k` and `graph.neighbors`.
void BuildPairs(NeighborGraph* graph, int num_threads = 1);

}  // namespace lpd::energy

#endif  // LPD_ENERGY_NEIGHBOR_GRAPH_H_
