// lpd: how many of the input points the problem holds.
//
// k grows with the density (neighborhood_size.h), and a run's time and memory grow like n k.
// When n k exceeds options.max_problem_size, a random subsample is solved instead and the
// result is extended to every point (subsample_extension.h). The subsample's k is chosen on
// the subsample itself, and its size n_s is set so that n_s k(n_s) meets the budget. The same
// surface with the same noise, sampled at any density past the budget, therefore gives the
// same subsample size and the same k: beyond the budget, the result no longer depends on the
// density. On the 1M-point cad_part at 0.5% noise, the whole cloud at k = 91 gives 1.30e-3 of
// the diagonal in 120 s; a subsample of 250K at k = 73 gives 0.56e-3 (docs/method.md).
//
// A subsample is also solved where the probe cannot read the noise: past its plane readings
// (LastPlaneReadRatio) on a cloud with thin parts' sides too close to split
// (PlaneReadingWeight), the cloud is thinned until the probe reads under kReadableRatio
// spacings, so that its neighbourhoods span more noise deviations (a thin cylinder of radius
// 2 noise deviations at 50,000 points: P2M x 1e4 4.26 -> 1.86; docs/method.md, "Noise the
// probe cannot read"). That search starts from the budget's choice, whose probes are cheap.
#ifndef LPD_SOLVERS_THINNING_H_
#define LPD_SOLVERS_THINNING_H_

#include <vector>

#include "energy/point3.h"
#include "solvers/neighborhood_size.h"

namespace lpd::solvers {

// Where a plane's reading is 0.50 of the true sigma (neighborhood_size.cc). Of 1.25, 1.27
// and 1.29, the one that left none of the thin parts at 50K and meshes at 100K points we
// measured worse than the whole cloud (docs/method.md).
constexpr double kReadableRatio = 1.27;

struct Thinning {
  std::vector<int> rows;  // the indices of the solved points, increasing; empty: all of them
  NeighborhoodSize size;  // k and its estimates, on the solved points
  int probes = 0;         // how many clouds (the whole one, then subsamples) were probed for k
};

// Throws std::invalid_argument as ChooseNeighborhoodSize.
Thinning ChooseThinning(const energy::PointList& points, const NeighborhoodSizeOptions& options,
                        int num_threads);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_THINNING_H_
