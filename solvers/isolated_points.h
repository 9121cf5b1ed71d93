// lpd: points far from every surface, found after the outlier passes.
//
// The outlier score (final_denoising.h) asks the neighbours' planes about a point. A few
// uniform outliers far from the surface escape it: a small group of them fits planes through
// each other and keeps a score just under the threshold (cad_part with 20% outliers: 3 to
// 26 such points per draw, 0.13-0.35 of the diagonal from the surface, which alone raise
// the kept points' mean distance by 4-20%). What they cannot hide is their isolation: a
// surface sampled with spacing s has its m-th neighbour at about s sqrt(m / pi), an outlier
// in the volume at 3-15x that. A kept point is flagged when the distance to its m-th
// nearest kept point exceeds `radius_factor` x both the median of that distance over the
// kept points and its median over the point's own m nearest kept points. The second test
// spares regions sampled more sparsely than the rest (a scan's far side): there every point
// is far from its neighbours, and so are they. Half of FANDISK sampled 10x more sparsely
// lost 1,416 of its points to the first test alone and loses none to both. On the twelve
// shared noisy models, the real scan and outlier-free inputs no output point comes within
// 2.7x the global median (docs/method.md), so the default 3x flags none there.
#ifndef LPD_SOLVERS_ISOLATED_POINTS_H_
#define LPD_SOLVERS_ISOLATED_POINTS_H_

#include <cstdint>
#include <string>
#include <vector>

#include "energy/point3.h"

namespace lpd::solvers {

struct IsolationOptions {
  int neighbors = 40;          // m: the rank of the neighbour whose distance is compared
  double radius_factor = 3.0;  // 0 turns the test off (the paper preset)

  bool IsValid(std::string* error) const;
};

// Flags (1) the points with kept[i] set whose distance to their m-th nearest kept point is
// more than radius_factor x the median of that distance over the kept points and over their
// own m nearest kept points. All zeros when the test is off or fewer than m + 1 points are
// kept. Any frame: the test is scale-free.
std::vector<uint8_t> FlagIsolatedPoints(const energy::PointList& points,
                                        const std::vector<uint8_t>& kept,
                                        const IsolationOptions& options, int num_threads);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_ISOLATED_POINTS_H_
