#include "energy/normalization.h"

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
  return (hi - lo).norm();
}

Frame ComputeNormalizingFrame(const PointList& points) {
  if (points.empty()) throw std::invalid_argument("the point set is empty");
  const double diagonal = BoundingBoxDiagonal(points);
  if (!(diagonal > 0.0)) {
    throw std::invalid_argument("all points coincide: the point set has no extent");
  }
  Frame frame;
  Point3 sum = Point3::Zero();
  for (const Point3& p : points) sum += p;
  frame.center = sum / static_cast<double>(points.size());
  frame.scale = diagonal;
  return frame;
}

}  // namespace lpd::energy
