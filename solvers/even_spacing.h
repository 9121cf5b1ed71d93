// lpd: even spacing over the denoised surface.
//
// The projection of Sec. 3.4 moves each point along the normal only, so the output keeps the
// tangential part of the noise: it is clumpier than a scan of the clean surface. On 10,000
// Poisson-disk samples of the bunny with 3% noise, even the exact normal projection (each
// sample moved back by the normal part of its own noise) is 3.68e-4 in Chamfer distance from
// the clean samples, where a second Poisson-disk sample is 2.00e-4.
//
// SpreadEvenly relaxes the points within their tangent planes by Lloyd's method, in rounds
// (Jacobi: every move from the positions of the round before): each point moves to the centroid
// of its cell among its 10 nearest (lloyd_cell.h),
//   C_i = { x in T_i : |x - p_i| <= |x - P_i p_j| } within their hull grown by sqrt(3) / 4 a,
//   p_i += min(1, kStep h / |c_i - p_i|) (c_i - p_i),   c_i the centroid of C_i,
// with T_i the tangent plane (normal n_i), P_i p_j a neighbour's offset projected into it
// (neighbours more than 45 degrees off it, across a thin part, left out), a the median distance
// from a point to its nearest neighbour in that round and h twice that distance in the first
// round. A point moves at most kStep = 0.4 h a round. Lloyd's rounds tend to a centroidal
// Voronoi tessellation, near a hexagonal lattice: of all samples of a plane, the one that
// leaves the smallest gaps. The grown hull ends a rim's cells half a lattice row beyond its
// outer points, where a hexagonal lattice's cells end, so that a rim neither spreads out nor
// draws in over the first rounds (docs/method.md, "Even spacing"). The caller carries each
// moved point along its own fitted surface (FinishDenoising). At a sharp edge, where a
// neighbour's normal n_j is more than 30 degrees off n_i, the move is projected onto
// e = n_i x n_j / |n_i x n_j| along the edge (n_j the most different normal); a point whose
// such neighbours give edges more than 30 degrees apart (a corner) stays. In a run on a
// subsample (subsample_extension.h), the subsample's points are spread, not the points
// projected onto its surfaces afterwards.
#ifndef LPD_SOLVERS_EVEN_SPACING_H_
#define LPD_SOLVERS_EVEN_SPACING_H_

#include <cstdint>
#include <vector>

#include "energy/neighbor_graph.h"
#include "energy/point3.h"

namespace lpd::solvers {

// `points` after `rounds` rounds of the relaxation above. Only the points with movable[i] move
// and bound cells (the others, such as outliers, are left out); `normals` are unit normals,
// and a point with a zero normal stays. `kernel` (optional): h where it holds a value over 0, else
// h is measured as above and written to it. Deterministic for any thread count.
energy::PointList SpreadEvenly(const energy::PointList& points, const energy::PointList& normals,
                               const std::vector<uint8_t>& movable, int rounds,
                               int num_threads, double* kernel = nullptr);

// Shortens the move of each point with moved[i] from start[i] to (*spread)[i] so that it goes
// no farther along its own direction than the farthest of inputs[i] and its neighbours'
// inputs in `graph` does, less `margin` (the noise's deviation: the farthest of a rim's noisy
// inputs lies beyond the rim): the relaxation can carry the outputs at a rim or at a thin
// wall's top outward, past the end of the data (docs/method.md, "The spacing held within
// the inputs").
void HoldWithinInputs(const energy::PointList& start, const energy::PointList& inputs,
                      const energy::NeighborGraph& graph, const std::vector<uint8_t>& moved,
                      double margin, int num_threads, energy::PointList* spread);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_EVEN_SPACING_H_
