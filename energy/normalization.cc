#include "energy/normalization.h"

#include <cmath>
#include <stdexcept>

namespace lpd::energy {

double BoundingBoxDiagonal(const PointList& points) {
  if (points.size() < 2) return 0.0;
  Point3 lo = points.front();
  Point3 hi = points.front();
  for (const Point3& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Point3 extent = hi - lo;
  const double diagonal = extent.norm();
  // The plain norm over- or underflows for coordinates near 1e+155 or 1e-155; the scaled one
  // is exact there (and kept out of the common case, whose results it would change in the
  // last bit).
  if (std::isfinite(diagonal) && (diagonal > 0.0 || extent.isZero(0.0))) return diagonal;
  return extent.stableNorm();
}

Frame ComputeNormalizingFrame(const PointList& points) {
  if (points.empty()) throw std::invalid_argument("the point set is empty");
  const double diagonal = BoundingBoxDiagonal(points);
  if (!std::isfinite(diagonal)) {
    throw std::invalid_argument(
        "the point set's extent overflows a double (coordinates differ by more than 1e308)");
  }
  if (!(diagonal > 0.0)) {
    throw std::invalid_argument("all points coincide: the point set has no extent");
  }
  Frame frame;
  const double n = static_cast<double>(points.size());
  Point3 sum = Point3::Zero();
  for (const Point3& p : points) sum += p;
  frame.center = sum / n;
  if (!frame.center.allFinite()) {  // the sum overflowed: average the scaled coordinates
    frame.center.setZero();
    for (const Point3& p : points) frame.center += p / n;
  }
  frame.scale = diagonal;
  return frame;
}

}  // namespace lpd::energy
