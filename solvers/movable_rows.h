// lpd: the output points the final steps move and read (even spacing aside): those not set
// aside (movable, not flagged outliers) with a nonzero normal. The offset feedback, the
// merged sides, the layers and the heights' smoothing take the same set.
#ifndef LPD_SOLVERS_MOVABLE_ROWS_H_
#define LPD_SOLVERS_MOVABLE_ROWS_H_

#include <cstdint>
#include <vector>

#include "energy/point3.h"

namespace lpd::solvers {

// The indices i, increasing, with movable[i] and a nonzero normals[i] (same sizes).
inline std::vector<int> MovableRowsWithNormal(const std::vector<uint8_t>& movable,
                                              const energy::PointList& normals) {
  std::vector<int> rows;
  for (size_t i = 0; i < normals.size(); ++i) {
    if (movable[i] && normals[i].squaredNorm() > 0.0) rows.push_back(static_cast<int>(i));
  }
  return rows;
}

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_MOVABLE_ROWS_H_
