#include "solvers/sphere_projection.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "energy/plane_projection.h"

namespace lpd::solvers {
namespace {

// R_i over the farthest partner's distance: 3 keeps every partner's weight above 0.6, so the
// fit averages over the whole neighbourhood (1.1: FANDISK 0.03 2.00e-3, 1.5: 1.96e-3, 3:
// 1.94e-3 mean distance over the diagonal).
constexpr double kRadiusFactor = 3.0;

// p on the plane t (normalized frame); p itself when t has no normal.
energy::Point3 OnPlane(const energy::Point3& p, const Eigen::Vector4d& t) {
  energy::Point3 projected = p;
  energy::ProjectOntoPlane(p, t, &projected);
  return projected;
}

// Weighted sums over a neighbourhood's anchors x and unit normals n: sum w, w x, w n, w x.n
// and w |x|^2.
struct WeightedMoments {
  double sw;
  Eigen::Vector3d sx, snrm;
  double sxn, sxx;
};

// Fits the algebraic sphere u0 + u.x + u4 |x|^2 to the moments (APSS closed form: u4 from
// the spread of x.n against |x|^2, then u, then u0) and moves p onto it. `ni` orients the
// normal; a vanishing u4 (relative to the neighbourhood's reach^2) means a plane, and a fit
// without a real sphere falls back to the plane t_i.
void ProjectOntoFittedSphere(const WeightedMoments& m, const Eigen::Vector3d& p,
                             const Eigen::Vector3d& ni, double reach, const Eigen::Vector4d& ti,
                             Eigen::Vector3d* projected, Eigen::Vector3d* normal) {
  const double sw = m.sw, sxn = m.sxn, sxx = m.sxx;
  const Eigen::Vector3d mean_x = m.sx / sw;
  const Eigen::Vector3d mean_n = m.snrm / sw;
  const double spread = sxx / sw - mean_x.squaredNorm();
  const double u4 = spread > 1e-300 ? 0.5 * (sxn / sw - mean_x.dot(mean_n)) / spread : 0.0;
  const Eigen::Vector3d u = mean_n - 2.0 * u4 * mean_x;
  const double u0 = -u.dot(mean_x) - u4 * sxx / sw;
  if (std::abs(u4) * std::sqrt(reach) < 1e-9 * u.norm()) {  // a plane: u0 + u.x = 0
    *normal = u.normalized();
    *projected = p - *normal * ((u.dot(p) + u0) / u.norm());
    return;
  }
  const Eigen::Vector3d center = -u / (2.0 * u4);
  const double radius2 = center.squaredNorm() - u0 / u4;
  const Eigen::Vector3d offset = p - center;
  if (radius2 <= 0.0 || offset.squaredNorm() == 0.0) {
    *projected = OnPlane(p, ti);
    *normal = ni;
    return;
  }
  *normal = offset.normalized();
  *projected = center + std::sqrt(radius2) * *normal;
  if (normal->dot(ni) < 0.0) *normal = -*normal;
}

}  // namespace

void ProjectOntoLocalSpheres(const energy::Problem& problem, const energy::Variables& v,
                             int num_threads, energy::PointList* points,
                             energy::PointList* normals) {
  const int n = problem.num_points();
  const auto& graph = problem.graph;
  points->resize(n);
  normals->resize(n);
  std::vector<Eigen::Vector3d> unit_normals(n), anchors(n);
  std::vector<uint8_t> has_normal(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector4d t = v.t.row(i).transpose();
    const double squared = t.head<3>().squaredNorm();
    has_normal[i] = squared > energy::kMinPlaneNormalSquaredNorm;
    unit_normals[i] = has_normal[i] ? Eigen::Vector3d(t.head<3>() / std::sqrt(squared))
                                    : Eigen::Vector3d::Zero();
    anchors[i] = OnPlane(problem.points[i], t);
  }
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d& p = problem.points[i];
    if (!has_normal[i]) {
      (*points)[i] = problem.frame.ToInput(p);
      (*normals)[i].setZero();
      continue;
    }
    const Eigen::Vector3d& ni = unit_normals[i];
    const int begin = graph.incident_offsets[i];
    const int end = graph.incident_offsets[i + 1];
    double reach = 0.0;
    for (int e = begin; e < end; ++e) {
      const auto& pair = graph.pairs[graph.incident_pairs[e]];
      const int j = pair[0] == i ? pair[1] : pair[0];
      reach = std::max(reach, (problem.points[j] - p).squaredNorm());
    }
    const double r2 = kRadiusFactor * kRadiusFactor * std::max(reach, 1e-300);
    // Weighted sums over i (weight 1) and its partners: sum w, w x, w n, w x.n, w |x|^2.
    double sw = 1.0, sxn = anchors[i].dot(ni), sxx = anchors[i].squaredNorm();
    Eigen::Vector3d sx = anchors[i], snrm = ni;
    for (int e = begin; e < end; ++e) {
      const int pair_index = graph.incident_pairs[e];
      const auto& pair = graph.pairs[pair_index];
      const int j = pair[0] == i ? pair[1] : pair[0];
      if (!has_normal[j]) continue;
      const double falloff = 1.0 - (problem.points[j] - p).squaredNorm() / r2;
      if (falloff <= 0.0) continue;
      const double w = v.m[pair_index] * std::pow(falloff, 4);
      const Eigen::Vector3d nj = unit_normals[j].dot(ni) < 0.0 ? -unit_normals[j]
                                                                : unit_normals[j];
      const Eigen::Vector3d& x = anchors[j];
      sw += w;
      sx += w * x;
      snrm += w * nj;
      sxn += w * x.dot(nj);
      sxx += w * x.squaredNorm();
    }
    Eigen::Vector3d projected, normal;
    ProjectOntoFittedSphere(WeightedMoments{sw, sx, snrm, sxn, sxx}, p, ni, reach,
                            v.t.row(i).transpose(), &projected, &normal);
    (*points)[i] = problem.frame.ToInput(projected);
    (*normals)[i] = normal;
  }
}

}  // namespace lpd::solvers
