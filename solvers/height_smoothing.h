// lpd: the output's heights along its normals smoothed over its nearest outputs, in pairs of
// rounds that do not shrink its curved parts (Taubin, "A signal processing approach to fair
// surface design", SIGGRAPH 1995).
//
// Each output is its input projected onto a surface fitted around it (the blend of its
// neighbours' spheres, sphere_projection.h), and neighbouring outputs' surfaces differ by
// their own fitting noise, so the output's heights along the normals jitter from point to
// point over a few spacings (docs/method.md, "The heights smoothed"). The neighbours N_i of
// an output o_i (unit normal n_i) are itself and those of its kHeightNeighbors nearest
// outputs o_j whose normals lie within kHeightMaxAngleDegrees of n_i (either sign) and whose
// heights n_i.(o_j - o_i) lie within `band` of it (the caller's: kHeightBandDeviations noise
// deviations): an edge's other face and a thin part's other side do not count. They are
// read once, on the outputs as given, and each round then moves every o_i along n_i by
//   f median_{j in N_i} n_i.(o_j - o_i)
// (Jacobi: every move from the positions of the round before). The median, not the mean:
// a thin part's outputs left between its two layers, within the band of a layer's points,
// would pull them off their layer (untuned plates and sheets at 10K: their mean P2M +0.3 to
// +1.5% with the mean, -0.4 to +0.1% with the median; docs/method.md, "The heights
// smoothed").
// f = kTaubinLambda smooths the heights and shrinks a curved surface by about its curvature
// times the neighbours' spread; the round after, f = kTaubinMu (|mu| > lambda) inflates it
// back. The pair damps the jitter over a few neighbours and passes the smooth shape: on
// 2,000 points of a unit sphere, two pairs change the mean radius by +3.6e-4, four rounds
// at lambda alone by -9.6e-3.
// In a run on a subsample (subsample_extension.h), the subsample's outputs are smoothed,
// not the points projected onto its surfaces afterwards, as in even spacing.
#ifndef LPD_SOLVERS_HEIGHT_SMOOTHING_H_
#define LPD_SOLVERS_HEIGHT_SMOOTHING_H_

#include <cstdint>
#include <vector>

#include "energy/point3.h"

namespace lpd::solvers {

constexpr int kHeightNeighbors = 8;
constexpr double kHeightBandDeviations = 2.0;
constexpr double kHeightMaxAngleDegrees = 20.0;
constexpr double kTaubinLambda = 0.63;
constexpr double kTaubinMu = -0.67;

// `outputs` after `pairs` pairs of rounds of the smoothing above, neighbours' heights within
// `band` (the frame of `outputs`). Only the outputs with movable[i] and a nonzero normal
// move and count (outliers are left out). Deterministic for any thread count.
energy::PointList SmoothHeights(const energy::PointList& outputs,
                                const energy::PointList& normals,
                                const std::vector<uint8_t>& movable, double band, int pairs,
                                int num_threads);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_HEIGHT_SMOOTHING_H_
