#include "solvers/sphere_projection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "energy/plane_projection.h"

namespace lpd::solvers {
namespace {

// R_i over the farthest partner's distance: 3 keeps every partner's weight above 0.6, so the
// fit averages over the whole neighbourhood (1.1: FANDISK 0.03 2.00e-3, 1.5: 1.96e-3, 3:
// 1.94e-3 mean distance over the diagonal).
constexpr double kRadiusFactor = 3.0;

// Weighted sums over a neighbourhood's anchors x and unit normals n: sum w, w x, w n, w x.n
// and w |x|^2.
struct WeightedMoments {
  double sw;
  Eigen::Vector3d sx, snrm;
  double sxn, sxx;
};

LocalSurface TangentPlane(const Eigen::Vector4d& t, const Eigen::Vector3d& orientation) {
  LocalSurface surface;
  surface.kind = LocalSurface::Kind::kPlane;
  surface.plane = t;
  surface.orientation = orientation;
  return surface;
}

// Fits the algebraic sphere u0 + u.x + u4 |x|^2 to the moments (APSS closed form: u4 from
// the spread of x.n against |x|^2, then u, then u0). A vanishing u4 (relative to the
// neighbourhood's reach^2) means a plane, and a fit without a real sphere falls back to the
// plane t_i. `ni` orients the normal.
LocalSurface FitSphere(const WeightedMoments& m, const Eigen::Vector3d& ni, double reach,
                       const Eigen::Vector4d& ti) {
  const double sw = m.sw, sxn = m.sxn, sxx = m.sxx;
  const Eigen::Vector3d mean_x = m.sx / sw;
  const Eigen::Vector3d mean_n = m.snrm / sw;
  const double spread = sxx / sw - mean_x.squaredNorm();
  const double u4 = spread > 1e-300 ? 0.5 * (sxn / sw - mean_x.dot(mean_n)) / spread : 0.0;
  const Eigen::Vector3d u = mean_n - 2.0 * u4 * mean_x;
  const double u0 = -u.dot(mean_x) - u4 * sxx / sw;
  if (std::abs(u4) * std::sqrt(reach) < 1e-9 * u.norm()) {  // a plane: u0 + u.x = 0
    return TangentPlane(Eigen::Vector4d(u[0], u[1], u[2], u0), ni);
  }
  LocalSurface surface;
  surface.center = -u / (2.0 * u4);
  const double radius2 = surface.center.squaredNorm() - u0 / u4;
  if (radius2 <= 0.0) return TangentPlane(ti, ni);
  surface.kind = LocalSurface::Kind::kSphere;
  surface.radius = std::sqrt(radius2);
  surface.orientation = ni;
  return surface;
}

// The weighted moments of i's anchor (weight 1) and of its partners' anchors and normals.
WeightedMoments PartnerMoments(const energy::Problem& problem, const energy::Variables& v,
                               int i, const std::vector<LocalSurface>& planes,
                               const std::vector<Eigen::Vector3d>& anchors, double* reach) {
  const auto& graph = problem.graph;
  const Eigen::Vector3d& p = problem.points[i];
  const Eigen::Vector3d& ni = planes[i].orientation;
  const int begin = graph.incident_offsets[i];
  const int end = graph.incident_offsets[i + 1];
  *reach = 0.0;
  for (int e = begin; e < end; ++e) {
    const auto& pair = graph.pairs[graph.incident_pairs[e]];
    const int j = pair[0] == i ? pair[1] : pair[0];
    *reach = std::max(*reach, (problem.points[j] - p).squaredNorm());
  }
  const double r2 = kRadiusFactor * kRadiusFactor * std::max(*reach, 1e-300);
  WeightedMoments m{1.0, anchors[i], ni, anchors[i].dot(ni), anchors[i].squaredNorm()};
  for (int e = begin; e < end; ++e) {
    const int pair_index = graph.incident_pairs[e];
    const auto& pair = graph.pairs[pair_index];
    const int j = pair[0] == i ? pair[1] : pair[0];
    if (planes[j].kind == LocalSurface::Kind::kNone) continue;
    const double falloff = 1.0 - (problem.points[j] - p).squaredNorm() / r2;
    if (falloff <= 0.0) continue;
    const double w = v.m[pair_index] * std::pow(falloff, 4);
    const Eigen::Vector3d nj = planes[j].orientation.dot(ni) < 0.0 ? -planes[j].orientation
                                                                   : planes[j].orientation;
    const Eigen::Vector3d& x = anchors[j];
    m.sw += w;
    m.sx += w * x;
    m.snrm += w * nj;
    m.sxn += w * x.dot(nj);
    m.sxx += w * x.squaredNorm();
  }
  return m;
}

}  // namespace

bool LocalSurface::Project(const Eigen::Vector3d& p, Eigen::Vector3d* projected,
                           Eigen::Vector3d* normal) const {
  if (kind == Kind::kNone) return false;
  if (kind == Kind::kPlane) {
    energy::ProjectOntoPlane(p, plane, projected);
    *normal = plane.head<3>().normalized();
    return true;
  }
  const Eigen::Vector3d offset = p - center;
  if (offset.squaredNorm() == 0.0) {  // the centre: every direction is as near
    *projected = p + radius * orientation;
    *normal = orientation;
    return true;
  }
  *normal = offset.normalized();
  *projected = center + radius * *normal;
  if (normal->dot(orientation) < 0.0) *normal = -*normal;
  return true;
}

double LocalSurface::DistanceTo(const Eigen::Vector3d& p) const {
  switch (kind) {
    case Kind::kPlane:
      return std::abs(plane.head<3>().dot(p) + plane[3]) / plane.head<3>().norm();
    case Kind::kSphere:
      return std::abs((p - center).norm() - radius);
    case Kind::kNone:
      break;
  }
  return std::numeric_limits<double>::infinity();
}

std::vector<LocalSurface> TangentPlaneSurfaces(const energy::Variables& v) {
  const int n = static_cast<int>(v.t.rows());
  std::vector<LocalSurface> planes(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector4d t = v.t.row(i).transpose();
    const double squared = t.head<3>().squaredNorm();
    if (squared > energy::kMinPlaneNormalSquaredNorm) {
      planes[i] = TangentPlane(t, t.head<3>() / std::sqrt(squared));
    }
  }
  return planes;
}

std::vector<LocalSurface> FitLocalSpheres(const energy::Problem& problem,
                                          const energy::Variables& v, int num_threads) {
  const std::vector<LocalSurface> planes = TangentPlaneSurfaces(v);
  std::vector<Eigen::Vector3d> anchors(problem.points.begin(), problem.points.end());
  for (int i = 0; i < problem.num_points(); ++i) {
    if (planes[i].kind != LocalSurface::Kind::kNone) {
      energy::ProjectOntoPlane(problem.points[i], planes[i].plane, &anchors[i]);
    }
  }
  std::vector<LocalSurface> spheres(problem.num_points());
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int i = 0; i < problem.num_points(); ++i) {
    if (planes[i].kind == LocalSurface::Kind::kNone) continue;
    double reach = 0.0;
    const WeightedMoments moments = PartnerMoments(problem, v, i, planes, anchors, &reach);
    spheres[i] = FitSphere(moments, planes[i].orientation, reach, planes[i].plane);
  }
  return spheres;
}

double BlendAgreementScale(const energy::Problem& problem,
                           const std::vector<LocalSurface>& surfaces) {
  std::vector<double> squared_moves;
  squared_moves.reserve(problem.num_points());
  for (int i = 0; i < problem.num_points(); ++i) {
    Eigen::Vector3d on_surface, normal;
    if (surfaces[i].Project(problem.points[i], &on_surface, &normal)) {
      squared_moves.push_back((on_surface - problem.points[i]).squaredNorm());
    }
  }
  if (squared_moves.empty()) return 0.0;
  const auto middle = squared_moves.begin() + squared_moves.size() / 2;
  std::nth_element(squared_moves.begin(), middle, squared_moves.end());
  return kBlendAgreement * kBlendAgreement * *middle;
}

bool ProjectOntoBlend(const std::vector<LocalSurface>& surfaces, const int* candidates,
                      int count, const Eigen::Vector3d& p, double agreement_scale,
                      Eigen::Vector3d* projected, Eigen::Vector3d* normal) {
  // Each surface's projection of p and its normal, oriented like the first surface's; kept
  // per thread, so that the blends of a cloud allocate once.
  thread_local std::vector<Eigen::Vector3d> points, normals;
  points.clear();
  normals.clear();
  const LocalSurface* first = nullptr;
  for (int a = 0; a < count; ++a) {
    const LocalSurface& surface = surfaces[candidates[a]];
    Eigen::Vector3d on_surface, surface_normal;
    if (!surface.Project(p, &on_surface, &surface_normal)) continue;
    if (first == nullptr) first = &surface;
    points.push_back(on_surface);
    normals.push_back(surface_normal.dot(first->orientation) < 0.0 ? -surface_normal
                                                                    : surface_normal);
  }
  if (first == nullptr) return false;
  // The weighted mean about `reference`; 1 for every surface where the scale is 0.
  const auto weighted_mean = [&](const Eigen::Vector3d& reference) {
    Eigen::Vector3d position_sum = Eigen::Vector3d::Zero(), normal_sum = Eigen::Vector3d::Zero();
    double weight_sum = 0.0;
    for (size_t a = 0; a < points.size(); ++a) {
      double weight = 1.0;
      if (agreement_scale > 0.0) {
        weight = 1.0 / (1.0 + (points[a] - reference).squaredNorm() / agreement_scale);
        weight *= weight;
      }
      position_sum += weight * points[a];
      normal_sum += weight * normals[a];
      weight_sum += weight;
    }
    *projected = position_sum / weight_sum;
    *normal = normal_sum.normalized();
  };
  weighted_mean(points.front());
  if (agreement_scale > 0.0 && points.size() > 1) weighted_mean(Eigen::Vector3d(*projected));
  return true;
}

bool ProjectOntoSettledBlend(const std::vector<LocalSurface>& surfaces, const int* candidates,
                             int count, const Eigen::Vector3d& p, double agreement_scale,
                             Eigen::Vector3d* projected, Eigen::Vector3d* normal) {
  if (!ProjectOntoBlend(surfaces, candidates, count, p, agreement_scale, projected, normal)) {
    return false;
  }
  if (count < 2) return true;
  Eigen::Vector3d again, again_normal;
  if (ProjectOntoBlend(surfaces, candidates, count, *projected, agreement_scale, &again,
                       &again_normal)) {
    *projected += again_normal * again_normal.dot(again - *projected);
  }
  return true;
}

void ProjectOntoBlendedSurfaces(const energy::Problem& problem,
                                const std::vector<LocalSurface>& surfaces, int blend,
                                double agreement_scale, bool settled, int num_threads,
                                energy::PointList* points, energy::PointList* normals) {
  const int n = problem.num_points();
  const int count = std::min(blend, problem.k() + 1);
  const auto project = settled ? ProjectOntoSettledBlend : ProjectOntoBlend;
  points->resize(n);
  normals->resize(n);
#pragma omp parallel num_threads(num_threads)
  {
    std::vector<int> candidates(count);
#pragma omp for schedule(static)
    for (int i = 0; i < n; ++i) {
      candidates[0] = i;
      std::copy_n(problem.graph.NeighborsOf(i), count - 1, candidates.begin() + 1);
      Eigen::Vector3d projected, normal;
      if (project(surfaces, candidates.data(), count, problem.points[i], agreement_scale,
                  &projected, &normal)) {
        (*points)[i] = problem.frame.ToInput(projected);
        (*normals)[i] = normal;
      } else {
        (*points)[i] = problem.frame.ToInput(problem.points[i]);
        (*normals)[i].setZero();
      }
    }
  }
}

}  // namespace lpd::solvers
