// lpd: points given more than once, solved once.
//
// A cloud often holds the same point twice or more: files concatenated, a mesh's vertices
// exported once per face corner along seams and hard edges, overlapping tiles. A repeated
// point is no new sample of the surface, but the energy treats it as one: its pair weight
// beta_ij (problem.h) is the duplicate guard's ceiling, thousands of times a neighbour's, so
// the data-derived lambda (data_scaled_weights.h), set by the median point's pair weights,
// falls by orders of magnitude, and the probe reads the spacing as if the surface were
// sampled twice as densely. cad_part (5,000 points, 1% noise) given twice over came out with
// 99% of its points as features and 1.22x the single copy's distance (docs/robustness.md).
// So points with identical coordinates are solved as one, the first of them, and every copy
// takes its result.
#ifndef LPD_SOLVERS_DUPLICATE_POINTS_H_
#define LPD_SOLVERS_DUPLICATE_POINTS_H_

#include <vector>

#include "energy/point3.h"

namespace lpd::solvers {

// first[i]: the smallest index j with points[j] == points[i] coordinate for coordinate
// (first[i] == i for a point's first occurrence). A point with a non-finite coordinate is
// its own first occurrence. O(n log n), deterministic.
std::vector<int> FirstOccurrences(const energy::PointList& points);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_DUPLICATE_POINTS_H_
