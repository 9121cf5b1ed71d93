// lpd: points that nearly repeat an earlier one, solved once.
//
// A copy of a cloud that is not bit for bit the same (a float32 re-export merged with the
// float64 original, a tile written twice after a transform) puts every point a hair away from
// its twin. Like an exact repeat (duplicate_points.h), the twin is no new sample of the
// surface, but its pair weight beta_ij (problem.h, 1 / |p_i - p_j|^2) is hundreds of times a
// neighbour's, so the data-derived lambda collapses, and the noise probe reads low: cad_part
// (5,000 points, 1% noise) plus a copy moved by 0.02 spacings came out at 1.22x the single
// copy's distance (docs/robustness.md).
//
// A point is a near repeat of an earlier representative when it lies within
// kNearRepeatRadius local spacings of it; the local spacing is read from the distance to the
// kNearRepeatNeighbors-th nearest point, sqrt(pi / K) d_K (one point per spacing^2 of surface).
// Random samples have such close pairs too: 0.02-0.15% of the points of the shared inputs,
// where the noise spreads them in depth, up to pi 0.1^2 / 2 = 1.6% at noise far under the
// spacing. A few close pairs do no harm (the lambda rule and the probe take medians; a tenth
// of cad_part given twice comes out 1.007x the single copy's distance), so near repeats are
// merged only where they are kMinNearRepeatShare of the points or more.
#ifndef LPD_SOLVERS_NEAR_REPEATS_H_
#define LPD_SOLVERS_NEAR_REPEATS_H_

#include <vector>

#include "energy/point3.h"

namespace lpd::solvers {

inline constexpr int kNearRepeatNeighbors = 16;
inline constexpr double kNearRepeatRadius = 0.1;
inline constexpr double kMinNearRepeatShare = 0.05;
// Larger clouds are searched whole only where this many of their points, spread evenly over
// them, have kMinNearRepeatShare with a point within the radius (a 17-NN search of 1M
// points takes 5-6 s on 2 cores, the sample 0.1 s).
inline constexpr int kNearRepeatSample = 16384;

// representative[r] for each of `points`: r itself, or the earliest row whose point is its
// own representative and lies within kNearRepeatRadius local spacings of points[r] (read in
// increasing r). All rows are their own representatives when fewer than kMinNearRepeatShare
// of them would not be, or when there are at most kNearRepeatNeighbors points; past
// kNearRepeatSample points, also when fewer than that share of the sample has a point
// within the radius. The points
// must be finite and pairwise distinct (FirstOccurrences). Deterministic for any
// `num_threads`.
std::vector<int> NearRepeatRepresentatives(const energy::PointList& points, int num_threads);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_NEAR_REPEATS_H_
