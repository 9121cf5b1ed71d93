#include "experiments/shapes/surface_patches.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "experiments/shapes/angle_range.h"
#include "experiments/shapes/feature_curves.h"

namespace lpd::experiments {

using energy::Point3;

// ---- ConvexPolygon ----

ConvexPolygon::ConvexPolygon(std::vector<Point3> vertices, const Point3& outward)
    : vertices_(std::move(vertices)) {
  if (vertices_.size() < 3) throw std::invalid_argument("a polygon needs three vertices");
  Point3 twice_area_vector = Point3::Zero();  // Newell's method
  for (size_t a = 0; a < vertices_.size(); ++a) {
    twice_area_vector += vertices_[a].cross(vertices_[(a + 1) % vertices_.size()]);
  }
  area_ = 0.5 * twice_area_vector.norm();
  if (!(area_ > 0.0)) throw std::invalid_argument("a polygon has zero area");
  normal_ = twice_area_vector.normalized();
  if (normal_.dot(outward) < 0.0) {
    std::reverse(vertices_.begin(), vertices_.end());
    normal_ = -normal_;
  }
  for (size_t t = 1; t + 1 < vertices_.size(); ++t) {
    fan_areas_.push_back(
        0.5 * (vertices_[t] - vertices_[0]).cross(vertices_[t + 1] - vertices_[0]).norm());
  }
}

SurfacePoint ConvexPolygon::Sample(std::mt19937_64* rng) const {
  std::discrete_distribution<size_t> pick(fan_areas_.begin(), fan_areas_.end());
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const size_t t = pick(*rng) + 1;
  double u = unit(*rng), v = unit(*rng);
  if (u + v > 1.0) {  // fold the unit square onto the triangle, keeping uniformity
    u = 1.0 - u;
    v = 1.0 - v;
  }
  const Point3 p = vertices_[0] + u * (vertices_[t] - vertices_[0]) +
                   v * (vertices_[t + 1] - vertices_[0]);
  return {p, normal_};
}

double ConvexPolygon::Distance(const Point3& p) const {
  const double height = (p - vertices_[0]).dot(normal_);
  const Point3 foot = p - height * normal_;
  bool inside = true;
  for (size_t a = 0; a < vertices_.size() && inside; ++a) {
    const Point3& u = vertices_[a];
    const Point3& v = vertices_[(a + 1) % vertices_.size()];
    inside = (v - u).cross(foot - u).dot(normal_) >= 0.0;
  }
  if (inside) return std::abs(height);
  double best = INFINITY;  // outside a convex polygon the nearest point is on its boundary
  for (size_t a = 0; a < vertices_.size(); ++a) {
    best = std::min(best,
                    FeatureSegment{vertices_[a], vertices_[(a + 1) % vertices_.size()]}.Distance(p));
  }
  return best;
}

// ---- RevolvedSegment ----

Point3 RevolutionFrame::At(double r, double z, double angle) const {
  const Point3 binormal = axis.cross(reference);
  return origin + z * axis + r * (std::cos(angle) * reference + std::sin(angle) * binormal);
}

RevolvedSegment::RevolvedSegment(const RevolutionFrame& frame, double r0, double z0, double r1,
                                 double z1, double start, double sweep)
    : frame_(frame), r0_(r0), z0_(z0), r1_(r1), z1_(z1), start_(start), sweep_(sweep) {
  if (!(r0 >= 0.0 && r1 >= 0.0)) throw std::invalid_argument("profile radii must be >= 0");
  if (!(sweep > 0.0 && sweep <= 2.0 * M_PI + 1e-12)) {
    throw std::invalid_argument("sweep must be in (0, 2 pi]");
  }
  const double length = std::hypot(r1 - r0, z1 - z0);
  area_ = sweep * length * 0.5 * (r0 + r1);  // Pappus: sweep x length x mean radius
  if (!(area_ > 0.0)) throw std::invalid_argument("a revolved segment has zero area");
}

SurfacePoint RevolvedSegment::Sample(std::mt19937_64* rng) const {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // The area element is r ds dt and r is linear along the profile, so r^2 is uniform.
  double s = unit(*rng);
  if (r1_ != r0_) {
    const double r = std::sqrt(r0_ * r0_ + s * (r1_ * r1_ - r0_ * r0_));
    s = (r - r0_) / (r1_ - r0_);
  }
  const double angle = start_ + sweep_ * unit(*rng);
  const double r = r0_ + s * (r1_ - r0_);
  const double z = z0_ + s * (z1_ - z0_);
  const double length = std::hypot(r1_ - r0_, z1_ - z0_);
  const double normal_r = (z1_ - z0_) / length;  // profile direction turned by -90 degrees
  const double normal_z = -(r1_ - r0_) / length;
  const Point3 radial = frame_.At(1.0, 0.0, angle) - frame_.origin;
  return {frame_.At(r, z, angle), normal_r * radial + normal_z * frame_.axis};
}

double RevolvedSegment::Distance(const Point3& p) const {
  const Point3 w = p - frame_.origin;
  const double z = w.dot(frame_.axis);
  const Point3 radial = w - z * frame_.axis;
  const Point3 binormal = frame_.axis.cross(frame_.reference);
  const double angle = std::atan2(radial.dot(binormal), radial.dot(frame_.reference));
  // The distance to the point (r, z', t) grows with the angle between t and p's meridian,
  // for every profile point alike: the nearest meridian is the in-range angle closest to p's.
  const double nearest = ClosestAngleInRange(angle, start_, sweep_);
  return FeatureSegment{frame_.At(r0_, z0_, nearest), frame_.At(r1_, z1_, nearest)}.Distance(p);
}

// ---- Sphere ----

Sphere::Sphere(const Point3& center, double radius) : center_(center), radius_(radius) {
  if (!(radius > 0.0)) throw std::invalid_argument("sphere radius must be > 0");
}

double Sphere::Area() const { return 4.0 * M_PI * radius_ * radius_; }

SurfacePoint Sphere::Sample(std::mt19937_64* rng) const {
  std::normal_distribution<double> normal(0.0, 1.0);
  Point3 direction;
  do {
    direction = Point3(normal(*rng), normal(*rng), normal(*rng));
  } while (direction.squaredNorm() < 1e-20);
  direction.normalize();
  return {center_ + radius_ * direction, direction};
}

double Sphere::Distance(const Point3& p) const { return std::abs((p - center_).norm() - radius_); }

}  // namespace lpd::experiments
