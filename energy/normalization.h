// lpd: the similarity transform between the input frame and the normalized frame.
//
// The method's constants (mu_l = 5e-9 is a squared distance, Table 2) assume a unit-size
// input (Sec. 4.1, "rescaled to fit a unit cube"). As in the paper's reference
// implementation, a point p is mapped to (p - c) / s with c the centroid and s the length of
// the bounding-box diagonal, so that the normalized cloud has diagonal 1.
#ifndef LPD_ENERGY_NORMALIZATION_H_
#define LPD_ENERGY_NORMALIZATION_H_

#include "energy/point3.h"

namespace lpd::energy {

struct Frame {
  Point3 center = Point3::Zero();  // c: centroid of the input.
  double scale = 1.0;              // s: bounding-box diagonal of the input, > 0.

  Point3 ToNormalized(const Point3& p) const { return (p - center) / scale; }
  Point3 ToInput(const Point3& p) const { return p * scale + center; }
};

// Length of the axis-aligned bounding-box diagonal of `points` (0 for fewer than 2 points).
double BoundingBoxDiagonal(const PointList& points);

// The frame that maps `points` to centroid 0 and bounding-box diagonal 1.
// Throws std::invalid_argument if the points are empty or all coincide.
Frame ComputeNormalizingFrame(const PointList& points);

}  // namespace lpd::energy

#endif  // LPD_ENERGY_NORMALIZATION_H_
