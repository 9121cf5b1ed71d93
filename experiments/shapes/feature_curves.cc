#include "experiments/shapes/feature_curves.h"

#include <algorithm>
#include <cmath>

#include "experiments/shapes/angle_range.h"

namespace lpd::experiments {

using energy::Point3;

double FeatureSegment::Distance(const Point3& p) const {
  const Point3 direction = b - a;
  const double length_squared = direction.squaredNorm();
  double s = 0.0;
  if (length_squared > 0.0) s = std::clamp((p - a).dot(direction) / length_squared, 0.0, 1.0);
  return (p - (a + s * direction)).norm();
}

double FeatureArc::Distance(const Point3& p) const {
  const Point3 w = p - center;
  const double height = w.dot(axis);
  const Point3 radial = w - height * axis;
  const Point3 binormal = axis.cross(reference);
  const double angle = std::atan2(radial.dot(binormal), radial.dot(reference));
  // The distance to a circle point grows with the angle between it and p's meridian, so the
  // nearest arc point lies at the in-range angle closest to p's.
  const double nearest = ClosestAngleInRange(angle, start, sweep);
  const Point3 q =
      center + radius * (std::cos(nearest) * reference + std::sin(nearest) * binormal);
  return (p - q).norm();
}

}  // namespace lpd::experiments
