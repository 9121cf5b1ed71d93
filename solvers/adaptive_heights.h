// lpd: each output's height refitted at the widest scale around it that its neighbours agree
// on: local quadratic height fits over nested neighbourhoods, the scale picked by the
// intersection of confidence intervals (ICI; Goldenshluger and Nemirovski 1997, Katkovnik
// 1999, after Lepski 1991).
//
// After the solve and the steps after it, the output's error has two parts: the error every
// local fit shares with its neighbours (smooth over a neighbourhood), and the point-to-point
// jitter the steps leave. A height fitted over more outputs averages more of both where the
// surface is smooth at that scale, and follows the shape less where it is not. One scale for
// the whole cloud cannot serve both: a larger k helps the bumpy cube and the plates at 50K 1%
// and harms the bunny and the knight (docs/method.md, "Heights at an adaptive scale"). Here
// each output chooses its own.
//
// For an output o_i with unit normal n_i, its neighbours are the outputs among its
// kAdaptiveSearched nearest whose normals lie within kAdaptiveMaxAngleDegrees of n_i (either
// sign) and whose heights z = n_i.(o_j - o_i) lie within
//   kJitterBandDeviations r + kBandSlope d,
// d the distance from o_i along the tangent plane and r = 1.4826 x the median over the
// outputs of the median |z| of each one's first kJitterNeighbors within the angle among its
// 2 kJitterNeighbors + 1 nearest (the jitter's deviation):
// an edge's other face and a thin part's other side do not count; a tilted normal does not
// shut out the far neighbours of a flat part. Over the first m of them, for m in
// kAdaptiveScales, the height field z = a + b.(u, v) + (u, v) C (u, v)^T is fitted by least
// squares, in the frame (u, v) of the tangent plane: a_m estimates o_i's height off the
// surface, with variance g L_m, L_m = (X^T X)^-1_00 and g the median over the outputs of the
// residual variance of the first scale's fits. The chosen a is the last a_m whose interval
// a_m +- kIntervalHalfWidth sqrt(g L_m) meets the intervals of every scale before it (bias
// moves a_m off the others' intervals as the fit widens over a feature or a curved detail),
// and o_i moves by a n_i. Every fit reads the outputs as given (Jacobi), so the result does
// not depend on the order of the points or the thread count. The default runs it only where
// the probe reads the noise narrower than the spacing: wider, the outputs' error is mostly
// the offset their fits share, and taking the jitter away raises P2M's mesh-to-result half
// (docs/method.md).
#ifndef LPD_SOLVERS_ADAPTIVE_HEIGHTS_H_
#define LPD_SOLVERS_ADAPTIVE_HEIGHTS_H_

#include <array>
#include <cstdint>
#include <vector>

#include "energy/point3.h"

namespace lpd::solvers {

// The neighbourhood sizes tried, smallest first (the first: twice the fit's 6 unknowns).
constexpr std::array<int, 10> kAdaptiveScales = {12, 16, 24, 32, 48, 64, 96, 128, 192, 256};
constexpr int kAdaptiveSearched = 257;  // the largest scale, and the output itself
constexpr int kJitterNeighbors = 12;
constexpr double kAdaptiveMaxAngleDegrees = 20.0;
constexpr double kJitterBandDeviations = 3.0;
constexpr double kBandSlope = 0.176;  // tan 10 degrees
constexpr double kIntervalHalfWidth = 2.0;

// `outputs` with each output's height refitted as above. Only the outputs with movable[i]
// and a nonzero normal move and count (outliers are left out). Deterministic for any thread
// count.
energy::PointList RefitHeightsAtAdaptiveScale(const energy::PointList& outputs,
                                              const energy::PointList& normals,
                                              const std::vector<uint8_t>& movable,
                                              int num_threads);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_ADAPTIVE_HEIGHTS_H_
