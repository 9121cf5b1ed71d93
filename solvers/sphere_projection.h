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
//
// Each fit still carries the noise of its own neighbourhood. By default a point is therefore
// moved to the mean of its projections onto the surfaces of itself and of its nearest
// neighbours (30 surfaces or more, FinalDenoisingOptions::blended_surfaces): a partition of
// unity over overlapping local fits, as in MLS. On the shared FANDISK and JOINT inputs it
// lowers the mean distance by 4-8% (docs/method.md).
#ifndef LPD_SOLVERS_SPHERE_PROJECTION_H_
#define LPD_SOLVERS_SPHERE_PROJECTION_H_

#include <vector>

#include <Eigen/Core>

#include "energy/problem.h"
#include "energy/variables.h"

namespace lpd::solvers {

// The surface a point is projected onto, in the normalized frame: a sphere, a plane
// u0 + u.x = 0, or none (the point stays and has no normal). `orientation` is the unit normal
// of t_i, which the projected normal is made to agree with.
struct LocalSurface {
  enum class Kind { kNone, kPlane, kSphere };
  Kind kind = Kind::kNone;
  Eigen::Vector4d plane = Eigen::Vector4d::Zero();  // (u, u0); |u| need not be 1
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0.0;
  Eigen::Vector3d orientation = Eigen::Vector3d::Zero();

  // The nearest point of the surface to p and the unit normal there; false for kNone.
  bool Project(const Eigen::Vector3d& p, Eigen::Vector3d* projected,
               Eigen::Vector3d* normal) const;
  // |p - its projection|; infinity for kNone.
  double DistanceTo(const Eigen::Vector3d& p) const;
};

// The tangent plane t_i of every point, as a LocalSurface (the projection of Sec. 3.4).
std::vector<LocalSurface> TangentPlaneSurfaces(const energy::Variables& v);

// The algebraic sphere of every point of the problem (problem order).
std::vector<LocalSurface> FitLocalSpheres(const energy::Problem& problem,
                                          const energy::Variables& v, int num_threads);

// The blend's robustness (docs/method.md, "The blend of surfaces"): a surface whose projection
// of p lies d from the first surface's counts (1 + d^2 / s)^-2, with the scale s = c^2 m, c
// this value and m the median over the problem's points of the squared distance their own
// surface moves them (about the square of the noise, one scale for every point). Surfaces
// from across an edge or a thin part, and poorly fitted ones, move p elsewhere than p's own
// surface does and count little.
constexpr double kBlendAgreement = 4.0;

// s above for the problem's points and their `surfaces` (problem order); 0 when none of them
// has a surface.
double BlendAgreementScale(const energy::Problem& problem,
                           const std::vector<LocalSurface>& surfaces);

// p (normalized frame) moved to the weighted mean of its projections onto surfaces[j] for the
// `count` indices j of `candidates`, and its normal to the weighted mean of theirs, oriented
// like that of the first surface that has one; each weighs (1 + d^2 / agreement_scale)^-2,
// d its projection's distance from the first one's, and then, once more, from that weighted
// mean (one reweighting step of the M-estimator: the first surface's projection carries its
// own error, and weights centred on it lean the mean its way; docs/method.md, "The blend
// reweighted"). agreement_scale 0: a plain mean. False when none of them has a surface.
bool ProjectOntoBlend(const std::vector<LocalSurface>& surfaces, const int* candidates,
                      int count, const Eigen::Vector3d& p, double agreement_scale,
                      Eigen::Vector3d* projected, Eigen::Vector3d* normal);

// ProjectOntoBlend, settled: the blend's point q is projected onto the same blend once more,
// giving q' with normal n', and q moves along n' by n'.(q' - q). The first projection still
// carries the noisy p: each surface's nearest point to p lies off q along the surface by
// about p's height times the angle between their normals, and the agreement weights read
// those points; from q, on the blend, the surfaces are read where they nearly meet. Along
// n' only: the full second projection also moves q along the surface, and measured worse on
// curved meshes (docs/method.md, "The settled blend"). `normal` stays the first
// projection's. With one surface, or where q' is not found, it is ProjectOntoBlend.
bool ProjectOntoSettledBlend(const std::vector<LocalSurface>& surfaces, const int* candidates,
                             int count, const Eigen::Vector3d& p, double agreement_scale,
                             Eigen::Vector3d* projected, Eigen::Vector3d* normal);

// Each problem point i moved onto the blend of the surfaces of i and of its nearest
// min(blend, k + 1) - 1 neighbours in N(i) (blend = 1: its own surface, Sec. 3.4), weighted
// at `agreement_scale` (BlendAgreementScale of the same surfaces; 0: a plain mean), and
// settled there (ProjectOntoSettledBlend) if `settled`. `points` and `normals` in problem
// order and the input frame; a point without a surface stays where it is with a zero normal.
void ProjectOntoBlendedSurfaces(const energy::Problem& problem,
                                const std::vector<LocalSurface>& surfaces, int blend,
                                double agreement_scale, bool settled, int num_threads,
                                energy::PointList* points, energy::PointList* normals);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_SPHERE_PROJECTION_H_
