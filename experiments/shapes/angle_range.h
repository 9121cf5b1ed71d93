// lpd: angles about an axis, and whether they fall in a range [start, start + sweep].
#ifndef LPD_EXPERIMENTS_SHAPES_ANGLE_RANGE_H_
#define LPD_EXPERIMENTS_SHAPES_ANGLE_RANGE_H_

#include <cmath>

namespace lpd::experiments {

// `angle - start` wrapped into [0, 2 pi).
inline double AngleFromStart(double angle, double start) {
  const double two_pi = 2.0 * M_PI;
  double delta = std::fmod(angle - start, two_pi);
  if (delta < 0.0) delta += two_pi;
  return delta;
}

// The angle of the range [start, start + sweep] closest to `angle` (itself if inside).
inline double ClosestAngleInRange(double angle, double start, double sweep) {
  const double delta = AngleFromStart(angle, start);
  if (delta <= sweep) return start + delta;
  // Outside: compare the way back to `start` with the way forward to the range's end.
  const double past_end = delta - sweep;
  const double before_start = 2.0 * M_PI - delta;
  return past_end < before_start ? start + sweep : start;
}

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_SHAPES_ANGLE_RANGE_H_
