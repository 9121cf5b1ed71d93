// lpd: the whole method in one call: points in, denoised points and indicators out.
//
// Builds the problem (normalization, N, M, alpha, beta), runs Alg. 1 from its initialization
// (H = T = 0, L = M = S = 1), then the final denoising of Sec. 3.4. Inputs are never modified.
#ifndef LPD_SOLVERS_DENOISE_POINT_SET_H_
#define LPD_SOLVERS_DENOISE_POINT_SET_H_

#include <cstdint>
#include <string>
#include <vector>

#include "energy/normalization.h"
#include "energy/problem.h"
#include "solvers/alternating_minimizer.h"
#include "solvers/final_denoising.h"
#include "solvers/solver_summary.h"

namespace lpd::solvers {

struct DenoiseOptions {
  energy::ProblemOptions problem;            // k and the duplicate-point guard
  AlternatingMinimizer::Options minimizer;   // energy weights, schedule, threads
  FinalDenoisingOptions final_step;          // indicators and outlier removal

  bool IsValid(std::string* error) const;
};

struct DenoiseResult {
  // One entry per input point, in input order and frame.
  energy::PointList projected;       // p_i projected onto t_i
  energy::PointList normals;         // unit normal of t_i (zero if undefined)
  PointIndicators indicators;
  // True for the points that are in the output (not removed as outliers).
  std::vector<uint8_t> kept;
  int num_outliers = 0;              // flagged by the indicator
  int num_removed = 0;               // actually removed
  int num_features = 0;
  std::string removal_note;          // why flagged outliers were kept, if they were
  SolverSummary summary;
  double setup_seconds = 0.0;        // normalization and k-NN graph
  double total_seconds = 0.0;
};

// Throws std::invalid_argument with a one-line reason on invalid options or input.
DenoiseResult DenoisePointSet(const energy::PointList& points, const DenoiseOptions& options,
                              const AlternatingMinimizer::IterationCallback& callback = nullptr);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_DENOISE_POINT_SET_H_
