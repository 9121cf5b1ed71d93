// lpd: the cell a point owns among its neighbours within its tangent plane, for the Lloyd
// relaxation of the even spacing (even_spacing.h).
//
// Given the neighbours' offsets s_a from the point in a plane (2D), the cell is
//   C = { x : |x| <= |x - s_a| for every a } intersected with H_m,
// the Voronoi cell of the origin, with H_m the convex hull of the origin and the s_a grown
// outward by m: each hull edge moved by m along its outer normal. Inside a surface the hull
// holds the cell and changes nothing; at a rim it stops the cell m beyond the outermost points.
// Lloyd's method moves each point to its cell's centroid (Lloyd 1982; Du, Faber and Gunzburger
// 1999, centroidal Voronoi tessellations).
#ifndef LPD_SOLVERS_LLOYD_CELL_H_
#define LPD_SOLVERS_LLOYD_CELL_H_

#include <Eigen/Core>

namespace lpd::solvers {

// The most neighbours ClippedCellCentroid takes.
constexpr int kMaxCellSites = 32;

// The centroid of C above for the `count` offsets `sites` (count <= kMaxCellSites; offsets of
// zero length are ignored) and margin m = `margin` >= 0. Returns false where the cell has no
// area (no sites, or all of them on one line through the origin with a zero margin).
bool ClippedCellCentroid(const Eigen::Vector2d* sites, int count, double margin,
                         Eigen::Vector2d* centroid);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_LLOYD_CELL_H_
