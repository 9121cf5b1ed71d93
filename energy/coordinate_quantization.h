// lpd: the noise that storing coordinates on a grid adds.
//
// Coordinates written with a fixed step q (a LAS file's scale factor, a fixed number of
// decimals, float32 far from the origin) carry a rounding error uniform on [-q/2, q/2], of
// deviation q / sqrt(12), however clean the surface. Where q is comparable to the spacing, a
// neighbourhood's points lie on a few exact planes (terraces of a tilted surface), more than
// half of the residuals from a fitted plane are exactly 0, and a median-based noise estimate
// reads 0: mu_l fell to the smallest double and every point was flagged an outlier (a tilted
// plane rounded to 1.8x its spacing lost 22% of its points). A residual scale is therefore
// never taken below the grid's rounding noise.
#ifndef LPD_ENERGY_COORDINATE_QUANTIZATION_H_
#define LPD_ENERGY_COORDINATE_QUANTIZATION_H_

#include "energy/point3.h"

namespace lpd::energy {

// sqrt(mean_a q_a^2 / 12), q_a the smallest gap between distinct values of coordinate a:
// the rounding noise along a normal, averaged over directions, in the points' units. For
// coordinates not on a grid q_a is tiny (about extent / n^2), and so is the result; 0 for
// fewer than 2 points. Read on at most 2^17 evenly strided points.
double QuantizationNoise(const PointList& points);

}  // namespace lpd::energy

#endif  // LPD_ENERGY_COORDINATE_QUANTIZATION_H_
