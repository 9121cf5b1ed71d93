// lpd: the fixed data of the energy of Eq. (5): normalized points, N, M, alpha_i, beta_ij.
//
// Symbols (Sec. 3.1):
//   q_i     = (p_i, 1), p_i the normalized input point
//   alpha_i = sum_{j in N(i)} |p_i - p_j|^2 / |N(i)|                      (area weight)
//   beta_ij = (alpha_i / |N(i)| + alpha_j / |N(j)|) / |p_i - p_j|^2        (pair weight)
// Duplicate points make |p_i - p_j| = 0 and beta_ij unbounded; both |p_i - p_j|^2 in beta_ij
// and alpha_i are therefore floored at `min_squared_distance_ratio` times the mean of alpha.
#ifndef LPD_ENERGY_PROBLEM_H_
#define LPD_ENERGY_PROBLEM_H_

#include <string>
#include <vector>

#include "energy/neighbor_graph.h"
#include "energy/normalization.h"
#include "energy/large_vector.h"

namespace lpd::energy {

struct ProblemOptions {
  // k = |N(i)|, the number of nearest neighbours (paper: 20, 50..150 for heavy noise).
  int k = 20;
  // Floor of |p_i - p_j|^2 and alpha_i, as a fraction of mean_i alpha_i (duplicate guard):
  // pairs closer than 1% of the RMS neighbour distance count as that far apart.
  double min_squared_distance_ratio = 1e-4;
  // N(i) from p_i's own side of a thin part (BuildNeighborGraph; paper: false).
  bool split_sheets = true;
  // How far thin regions grow (BuildNeighborGraph); StartDenoising makes it kEverywhere
  // where the noise is as wide as the spacing.
  ThinRegionGrowth thin_region_growth = ThinRegionGrowth::kWhereCommon;
  // The neighbourhoods the splits are judged on (BuildNeighborGraph); StartDenoising judges
  // them on kSheetSplitPoints where the probe finds few thin candidates.
  SplitNeighborhood split_neighborhood = SplitNeighborhood::kCandidates;
  bool IsValid(std::string* error) const;
};

struct Problem {
  Frame frame;            // input frame <-> normalized frame
  PointList points;       // p_i, normalized (centroid 0, bounding-box diagonal 1)
  NeighborGraph graph;    // N and M
  std::vector<double> alpha;  // alpha_i, one per point
  LargeVector<double> beta;  // beta_ij, one per pair of M (graph.pairs order)
  // The rounding noise of the input's coordinate grid, normalized: the floor of every
  // residual scale (energy/coordinate_quantization.h).
  double quantization_noise = 0.0;

  int num_points() const { return static_cast<int>(points.size()); }
  int k() const { return graph.k; }
};

// Normalizes `input_points`, builds N and M and the weights. `searched`, when given, is the
// noise probe's search over these same points (BuildNeighborGraph). Throws
// std::invalid_argument with a one-line reason on invalid options, non-finite coordinates,
// too few points or a point set without extent.
Problem BuildProblem(const PointList& input_points, const ProblemOptions& options,
                     int num_threads = 1, const SplitSearch* searched = nullptr);

// The median of alpha_i (0 for an empty problem): the squared neighbourhood scale that the
// data-derived weights and the spacing estimate are expressed in.
double MedianAlpha(const Problem& problem);

// The sample spacing sqrt(2 pi median_alpha / k): alpha, the mean squared distance to k
// neighbours, is k spacing^2 / (2 pi) on a uniformly sampled disk.
double SpacingFromMedianAlpha(double median_alpha, int k);
// SpacingFromMedianAlpha of the problem's alpha_i and k (0 for an empty problem).
double SampleSpacing(const Problem& problem);

// Fills alpha and beta from problem->points and problem->graph (used by BuildProblem and by
// tests that construct graphs by hand), with `num_threads` threads.
void ComputeWeights(double min_squared_distance_ratio, Problem* problem, int num_threads = 1);

}  // namespace lpd::energy

#endif  // LPD_ENERGY_PROBLEM_H_
