// lpd: projection onto local algebraic spheres, a second-order alternative to the tangent-plane
// projection of Sec. 3.4 (the "higher-order local fits" of the paper's future work, Sec. 5).
//
// A plane through a curved neighbourhood sits off the surface by about kappa r^2 / 4 (the mean
// sagitta over a disk of radius r). Around each point i we fit the algebraic sphere
//   u(x) = u0 + u^T x + u4 |x|^2
// whose gradient best matches the unit normals n_j of the planes t_j and whose zero set passes
// closest to the points, over i and its partners j in M (APSS, Guennebaud and Gross 2007),
// weighted by
//   w_ij = m_ij (1 - |p_j - p_i|^2 / R_i^2)^4,   R_i = 3 max_j |p_j - p_i|,
// so that the feature processes m_ij (Eq. 7) keep neighbours across a sharp edge out of the
// fit. The normals are oriented to agree with n_i, and the points are the neighbours'
// projections onto their own planes t_j. p_i then moves to the nearest point of the sphere
// (or of the plane when u4 vanishes).
#ifndef LPD_SOLVERS_SPHERE_PROJECTION_H_
#define LPD_SOLVERS_SPHERE_PROJECTION_H_

#include "energy/problem.h"
#include "energy/variables.h"

namespace lpd::solvers {

// `points` and `normals`: in input order of the problem (problem order), input frame. Points
// whose plane t_i has no normal are left where they are with a zero normal.
void ProjectOntoLocalSpheres(const energy::Problem& problem, const energy::Variables& v,
                             int num_threads, energy::PointList* points,
                             energy::PointList* normals);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_SPHERE_PROJECTION_H_
