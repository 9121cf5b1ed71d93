// lpd: a memory order for the points that keeps neighbours close (Z-order / Morton curve).
//
// Every per-point and per-pair loop of Alg. 1 reads the planes of a point's neighbours; in
// the input's order (random for sampled shapes) those reads miss the cache once the planes
// outgrow it. Sorting by the Morton code of the point's cell in a 2^21 grid over the bounding
// box makes k-NN neighbours mostly nearby in memory.
#ifndef LPD_ENERGY_SPATIAL_ORDER_H_
#define LPD_ENERGY_SPATIAL_ORDER_H_

#include <cstdint>
#include <vector>

#include "energy/point3.h"

namespace lpd::energy {

// The Morton code of grid cell (x, y, z), each < 2^21: bit b of x, y, z goes to bit 3b,
// 3b + 1, 3b + 2 of the code.
uint64_t MortonCode(uint32_t x, uint32_t y, uint32_t z);

// A permutation `order` of 0..n-1 such that points[order[0]], points[order[1]], ... follow
// the Morton curve over the bounding box of the finite points (ties keep input order;
// non-finite points get the lowest code).
std::vector<int> MortonOrder(const PointList& points);

}  // namespace lpd::energy

#endif  // LPD_ENERGY_SPATIAL_ORDER_H_
