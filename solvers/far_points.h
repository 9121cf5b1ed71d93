// lpd: stray points far from the whole cloud, set aside before anything else.
//
// A scan's stray returns (a reflection, the sky, a second object in the distance) can lie
// thousands of times the object's size away. Left in, one such point sets the normalized
// frame (whose diagonal then spans it), and with it the noise and spacing estimates, k and
// every weight derived from them: one point at 1e5 on FANDISK's 10,000 first points moved the
// others by a median of 16.7 units in a cloud of diagonal 8. These points are found without
// a frame: the bulk of the cloud is the ball around the coordinate-wise median that holds
// `bulk_fraction` of the points; a point farther from the median than `factor` times that
// ball's radius is far. The rest is then denoised exactly as if the far points had never
// been there, and the far points are flagged as outliers.
#ifndef LPD_SOLVERS_FAR_POINTS_H_
#define LPD_SOLVERS_FAR_POINTS_H_

#include <cstdint>
#include <string>
#include <vector>

#include "energy/point3.h"

namespace lpd::solvers {

struct FarPointOptions {
  // Up to 1 - bulk_fraction of the points can be far without moving the bulk's radius.
  double bulk_fraction = 0.98;
  // 0 turns the test off (the paper preset). A real object's farthest points lie within a
  // few bulk radii (about 1.2 on the shared models); 100 leaves room for scans whose density
  // falls off with range.
  double factor = 100.0;

  bool IsValid(std::string* error) const;
};

// Flags (1) the points farther from the coordinate-wise median of `points` than `factor`
// times the radius around it that holds bulk_fraction of the points. All zeros when the test
// is off or that radius is 0 (most points coincide).
std::vector<uint8_t> FlagFarPoints(const energy::PointList& points,
                                   const FarPointOptions& options);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_FAR_POINTS_H_
