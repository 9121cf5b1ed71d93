#include "experiments/box_shape.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lpd::experiments {

using energy::Point3;

BoxShape::BoxShape(const Point3& center, const Point3& half_extents)
    : center_(center), half_extents_(half_extents) {
  if (!(half_extents.minCoeff() > 0.0)) {
    throw std::invalid_argument("box half extents must be > 0");
  }
}

energy::PointList BoxShape::SampleSurface(int count, std::mt19937_64* rng) const {
  const Point3& e = half_extents_;
  // Face pair a (normal along axis a) has area 4 e_b e_c per face.
  const double areas[3] = {e[1] * e[2], e[0] * e[2], e[0] * e[1]};
  std::discrete_distribution<int> pick_axis({areas[0], areas[1], areas[2]});
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::bernoulli_distribution pick_side(0.5);
  energy::PointList points;
  points.reserve(count);
  for (int n = 0; n < count; ++n) {
    const int axis = pick_axis(*rng);
    Point3 local;
    for (int c = 0; c < 3; ++c) local[c] = unit(*rng) * e[c];
    local[axis] = pick_side(*rng) ? e[axis] : -e[axis];
    points.push_back(center_ + local);
  }
  return points;
}

double BoxShape::DistanceToSurface(const Point3& p) const {
  const Point3 q = (p - center_).cwiseAbs() - half_extents_;  // per-axis signed excess
  const double outside = q.cwiseMax(0.0).norm();
  const double inside = std::min(q.maxCoeff(), 0.0);
  return outside > 0.0 ? outside : -inside;
}

double BoxShape::DistanceToEdges(const Point3& p) const {
  const Point3 q = (p - center_).cwiseAbs();
  double best = INFINITY;
  // An edge parallel to axis a sits at |x_b| = e_b, |x_c| = e_c for the other two axes.
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3;
    const int c = (a + 2) % 3;
    const double along = std::max(q[a] - half_extents_[a], 0.0);
    const double db = q[b] - half_extents_[b];
    const double dc = q[c] - half_extents_[c];
    best = std::min(best, std::sqrt(along * along + db * db + dc * dc));
  }
  return best;
}

}  // namespace lpd::experiments
