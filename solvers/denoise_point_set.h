// lpd: the whole method in one call: points in, denoised points and indicators out.
//
// Builds the problem (normalization, N, M, alpha, beta), minimizes Eq. (5) with Alg. 1 (or
// with the Ceres joint-solve baseline), then runs the final denoising of Sec. 3.4. Inputs are
// never modified.
#ifndef LPD_SOLVERS_DENOISE_POINT_SET_H_
#define LPD_SOLVERS_DENOISE_POINT_SET_H_

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "energy/normalization.h"
#include "energy/problem.h"
#include "solvers/alternating_minimizer.h"
#include "solvers/ceres_joint_solver.h"
#include "solvers/final_denoising.h"
#include "solvers/initial_state.h"
#include "solvers/solver_summary.h"

namespace lpd::solvers {

enum class Solver {
  kAlternating,  // Alg. 1, the paper's method
  kCeres,        // the joint-solve baseline
};
const char* SolverName(Solver solver);  // "alternating", "ceres"
bool ParseSolver(const std::string& name, Solver* solver);

struct DenoiseOptions {
  energy::ProblemOptions problem;            // k and the duplicate-point guard
  // Energy weights, Alg. 1's schedule and the thread count of every stage (the joint solve's
  // own num_threads is replaced by minimizer.num_threads).
  AlternatingMinimizer::Options minimizer;
  Solver solver = Solver::kAlternating;
  CeresJointSolver::Options joint;           // used when solver == kCeres
  // The start of the minimization; unset means kZero for Alg. 1 (as the paper does) and
  // kPlaneFit for the joint solve (which needs every h_i on the unit sphere).
  std::optional<Initialization> initialization;
  FinalDenoisingOptions final_step;          // indicators and outlier removal

  Initialization EffectiveInitialization() const;

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
                              const IterationCallback& callback = nullptr);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_DENOISE_POINT_SET_H_
