// lpd: a point projected onto a plane of the energy of Eq. (5), t = (n, d), as the final
// denoising of Sec. 3.4 does: p' = p - n (n^T p + d) / |n|^2.
#ifndef LPD_ENERGY_PLANE_PROJECTION_H_
#define LPD_ENERGY_PLANE_PROJECTION_H_

#include <Eigen/Core>

#include "energy/point3.h"

namespace lpd::energy {

// Planes whose normal part is shorter than this (t is a unit-scale 4-vector) are no planes.
constexpr double kMinPlaneNormalSquaredNorm = 1e-24;

// Sets *projected and returns true, or returns false when t has no normal.
inline bool ProjectOntoPlane(const Point3& p, const Eigen::Vector4d& t, Point3* projected) {
  const Eigen::Vector3d normal = t.head<3>();
  const double squared = normal.squaredNorm();
  if (!(squared > kMinPlaneNormalSquaredNorm)) return false;
  *projected = p - normal * ((normal.dot(p) + t[3]) / squared);
  return true;
}

}  // namespace lpd::energy

#endif  // LPD_ENERGY_PLANE_PROJECTION_H_
