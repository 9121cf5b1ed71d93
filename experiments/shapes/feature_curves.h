// lpd: sharp feature curves of procedural shapes (line segments and circular arcs).
//
// A ground-truth point is a feature point when it lies within a band around one of these
// curves; scoring the feature indicator of Sec. 3.4 needs only the exact distance to them.
#ifndef LPD_EXPERIMENTS_SHAPES_FEATURE_CURVES_H_
#define LPD_EXPERIMENTS_SHAPES_FEATURE_CURVES_H_

#include "energy/point3.h"

namespace lpd::experiments {

// The segment [a, b]; a == b is a single point (the apex of a cone).
struct FeatureSegment {
  energy::Point3 a;
  energy::Point3 b;

  double Distance(const energy::Point3& p) const;
};

// The arc of the circle of `radius` around `center` in the plane orthogonal to the unit
// `axis`, from angle `start` over `sweep` radians (sweep in (0, 2 pi]), where angle 0 points
// along the unit vector `reference` (orthogonal to `axis`) and angles turn by the right-hand
// rule about `axis`.
struct FeatureArc {
  energy::Point3 center;
  energy::Point3 axis;
  energy::Point3 reference;
  double radius = 0.0;
  double start = 0.0;
  double sweep = 0.0;

  double Distance(const energy::Point3& p) const;
};

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_SHAPES_FEATURE_CURVES_H_
