// lpd: what a minimization returns: termination, energies, and a per-step trace.
//
// Shared by the alternating driver (Alg. 1) and the joint solve (the validation solver).
// Sentinel values (termination FAILURE, message "Solve was not called") mark a summary that
// was never filled.
#ifndef LPD_SOLVERS_SOLVER_SUMMARY_H_
#define LPD_SOLVERS_SOLVER_SUMMARY_H_

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "energy/energy.h"

namespace lpd::solvers {

enum class TerminationType {
  kConvergence,    // relative energy change over the window fell below the tolerance
  kNoConvergence,  // reached the maximum number of iterations (the result is still usable)
  kUserAbort,      // a callback asked to stop
  kFailure,        // invalid options or a non-finite energy; the variables are not usable
};

const char* TerminationTypeName(TerminationType type);

// One block update of Alg. 1: which block, where in the schedule, the energy after it.
struct StepRecord {
  std::string block;        // "H", "L", "T", "M" or "S"
  int iteration = 0;        // outer iteration, from 1
  int inner_iteration = 0;  // inner (T, M, S) pass, from 1; 0 for the local step
  energy::EnergyBreakdown energy;  // after the update (only if Options::trace_blocks)
  double seconds = 0.0;     // wall time of the update itself
  int cg_iterations = -1;   // for "T": conjugate-gradient iterations; -1 otherwise
};

// One outer iteration of Alg. 1, or one iteration of the joint solve.
struct IterationRecord {
  int iteration = 0;                // from 1
  energy::EnergyBreakdown energy;   // at the end of the iteration
  double local_seconds = 0.0;       // H and L updates (Eqs. 10, 6); 0 for the joint solve
  double global_seconds = 0.0;      // all inner (T, M, S) passes (Eqs. 9, 7, 8); 0 likewise
  double seconds = 0.0;             // the whole iteration
  // Since the minimization started, leaving out energy evaluations made only for the trace
  // (the time axis of energy-versus-time comparisons).
  double elapsed_seconds = 0.0;
  int cg_iterations = 0;            // summed over the inner passes / linear solver iterations
  // The selectivities this iteration's line-process updates used (they differ from the
  // energy's only during graduated non-convexity).
  double mu_l = NAN;
  double mu_m = NAN;
  // RMS distance the output points (p_i projected onto t_i) moved in this iteration, in the
  // normalized frame (diagonal 1); NaN for the joint solve and for the first iteration.
  double point_motion = NAN;
};

// Called after every iteration; returning false stops the run (USER_ABORT).
using IterationCallback = std::function<bool(const IterationRecord&)>;

struct SolverSummary {
  TerminationType termination = TerminationType::kFailure;
  std::string message = "Solve was not called";
  energy::EnergyBreakdown initial_energy;
  energy::EnergyBreakdown final_energy;
  int num_iterations = 0;
  // The target mu_l the energies are evaluated with (the scale-aware one if it was chosen).
  double mu_l = NAN;
  // The eta and lambda used (given, or derived from the data: energy/data_scaled_weights.h).
  double eta = NAN;
  double lambda = NAN;
  std::vector<StepRecord> steps;
  std::vector<IterationRecord> iterations;
  double total_seconds = 0.0;

  bool IsSolutionUsable() const;
  // One line: termination, iterations, final energy, time.
  std::string BriefReport() const;
  // The brief report followed by one line per block update (or, without a block trace, per
  // iteration) with the per-term energies.
  std::string FullReport() const;
};

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_SOLVER_SUMMARY_H_
