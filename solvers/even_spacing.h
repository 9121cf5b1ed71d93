// lpd: even spacing over the denoised surface.
//
// The projection of Sec. 3.4 moves each point along the normal only, so the output keeps the
// tangential part of the noise: it is clumpier than a scan of the clean surface. On 10,000
// Poisson-disk samples of the bunny with 3% noise, even the exact normal projection (each
// sample moved back by the normal part of its own noise) is 3.68e-4 in Chamfer distance from
// the clean samples, where a second Poisson-disk sample is 2.00e-4.
//
// SpreadEvenly pushes nearest neighbours apart within each point's tangent plane, in rounds
// (Jacobi: every move from the positions of the round before):
//   f_i = sum_{j in the kNeighbors nearest} (p_i - p_j) / |p_i - p_j| exp(-4 |p_i - p_j|^2 / h^2)
//   p_i += kStep h P_i f_i / max(1, |P_i f_i|),   P_i = I - n_i n_i^T,
// with h twice the median distance from a point to its nearest neighbour (the repulsion of
// WLOP, Huang et al. 2009, without its attraction to the input: the caller carries each moved
// point along its own fitted surface, FinishDenoising). A point moves at most kStep h per
// round. At a sharp edge, where a neighbour's normal n_j is more than 30 degrees off n_i,
// P_i = e e^T instead, e = n_i x n_j / |n_i x n_j| along the edge (n_j the most different
// normal); a point whose such neighbours give edges more than 30 degrees apart (a corner)
// stays. In a run on a subsample (subsample_extension.h), the subsample's points are spread,
// not the points projected onto its surfaces afterwards.
#ifndef LPD_SOLVERS_EVEN_SPACING_H_
#define LPD_SOLVERS_EVEN_SPACING_H_

#include <cstdint>
#include <vector>

#include "energy/neighbor_graph.h"
#include "energy/point3.h"

namespace lpd::solvers {

// `points` after `rounds` rounds of the repulsion above. Only the points with movable[i] move
// and push (the others, such as outliers, are left out); `normals` are unit normals, and a
// point with a zero normal stays. `kernel` (optional): h where it holds a value over 0, else
// h is measured as above and written to it. Deterministic for any thread count.
energy::PointList SpreadEvenly(const energy::PointList& points, const energy::PointList& normals,
                               const std::vector<uint8_t>& movable, int rounds,
                               int num_threads, double* kernel = nullptr);

// Shortens the move of each point with moved[i] from start[i] to (*spread)[i] so that it goes
// no farther along its own direction than the farthest of inputs[i] and its neighbours'
// inputs in `graph` does, less `margin` (the noise's deviation: the farthest of a rim's noisy
// inputs lies beyond the rim): the repulsion pushes the outputs at a rim or at a thin wall's
// top outward each round, past the end of the data (docs/method.md, "The spacing held within
// the inputs").
void HoldWithinInputs(const energy::PointList& start, const energy::PointList& inputs,
                      const energy::NeighborGraph& graph, const std::vector<uint8_t>& moved,
                      double margin, int num_threads, energy::PointList* spread);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_EVEN_SPACING_H_
