// lpd: the figures of the learned denoisers' benchmark (ScoreDenoise, IterativePFN,
// P2P-Bridge and the papers that follow their protocol), in the unit-sphere frame:
//
//   unit sphere: centre c = (max + min) / 2 of a point set, radius R = max |p - c|;
//   CD  = mean_{x in X} min_{y in Y} |x - y|^2 + mean_{y in Y} min_{x in X} |x - y|^2, with
//         X the result and Y the clean samples, both in the clean samples' unit sphere;
//   P2M = mean_{x in X} d(x, M)^2 + mean_{f in M} d(f, X)^2, with M the clean mesh and X in
//         the mesh vertices' unit sphere, f its triangles.
//
// Both are reported times 1e4. For a procedural shape the triangles are replaced by dense
// area-uniform samples of its surface (an area-weighted mean rather than a per-triangle one).
#ifndef LPD_EXPERIMENTS_EVALUATION_BENCHMARK_METRICS_H_
#define LPD_EXPERIMENTS_EVALUATION_BENCHMARK_METRICS_H_

#include <vector>

#include "energy/point3.h"
#include "experiments/evaluation/ground_truth.h"
#include "experiments/shapes/noise.h"  // UnitSphereOf

namespace lpd::experiments {

// The distance from each of `from` to the nearest of `to` (k-d tree, in parallel).
std::vector<double> NearestDistances(const energy::PointList& from, const energy::PointList& to,
                                     int num_threads);

// CD x 1e4 of `result` against `clean`. Throws std::invalid_argument if either is empty.
double ChamferDistanceX1e4(const energy::PointList& result, const energy::PointList& clean,
                           int num_threads);

// P2M x 1e4 of `result` against the truth's surface; NaN when the truth has no surface
// (a clean point set). Throws std::invalid_argument if `result` is empty.
double PointToMeshDistanceX1e4(const energy::PointList& result, const GroundTruth& truth,
                               int num_threads);

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_EVALUATION_BENCHMARK_METRICS_H_
