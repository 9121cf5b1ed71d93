// lpd: the wider neighbourhoods the sheet split is judged on, searched once.
//
// The noise probe (solvers/neighborhood_size.h) searches the kSheetSplitPoints nearest of
// every point (or the max_k + 1 nearest, if more, up to 2 kSheetSplitPoints) and splits each
// point's kSheetSplitPoints nearest (sheet_split.h). BuildNeighborGraph needs that search
// whenever it needs no more neighbours (k <= max_k at the default max_k), and the same
// splits whenever it judges them on kSheetSplitPoints (always where 2k + 1 <=
// kSheetSplitPoints). Kept from the probe, they spare the graph a second k-d tree search
// over the same points.
#ifndef LPD_ENERGY_SPLIT_SEARCH_H_
#define LPD_ENERGY_SPLIT_SEARCH_H_

#include <vector>

#include "energy/sheet_split.h"
#include "energy/large_vector.h"

namespace lpd::energy {

struct SplitSearch {
  // Points searched around each point, the point itself included (it is usually first).
  int searched = 0;
  // nearest[i * searched + a]: the a-th nearest of point i (NearestNeighbors order). Its
  // first m entries are those a search of the m nearest finds, in the same order.
  LargeVector<int> nearest;
  // splits[i] = SplitSheets over the first split_points of nearest[i * searched, ...).
  int split_points = 0;
  std::vector<SheetSplit> splits;

  int num_points() const { return searched > 0 ? static_cast<int>(splits.size()) : 0; }
  const int* NearestOf(int i) const {
    return nearest.data() + static_cast<size_t>(i) * searched;
  }
};

}  // namespace lpd::energy

#endif  // LPD_ENERGY_SPLIT_SEARCH_H_
