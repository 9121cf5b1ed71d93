// lpd: the alternating restricted minimization of Alg. 1 (Sec. 3.3).
//
// Each outer iteration runs the local step (H by Eq. 10, then L by Eq. 6) and then
// `inner_iterations` global passes (T by Eq. 9, M by Eq. 7, S by Eq. 8). Every update is the
// exact minimizer of Eq. (5) over its block, so once H is on the unit sphere the energy never
// increases. The run stops after `max_iterations`, or when the total energy changed by less
// than `energy_tolerance` (relative) over the last `energy_window` iterations.
#ifndef LPD_SOLVERS_ALTERNATING_MINIMIZER_H_
#define LPD_SOLVERS_ALTERNATING_MINIMIZER_H_

#include <string>

#include "energy/energy_parameters.h"
#include "energy/problem.h"
#include "energy/variables.h"
#include "solvers/solver_summary.h"
#include "solvers/tangent_plane_smoothing.h"

namespace lpd::solvers {

class AlternatingMinimizer {
 public:
  struct Options {
    // ---- energy (Eq. 5, Table 2) ----
    energy::EnergyParameters energy;

    // ---- schedule (Alg. 1) ----
    // Outer iterations at most (maxIter of Alg. 1; the reference implementation runs 5).
    int max_iterations = 5;
    // (T, M, S) passes per outer iteration (Alg. 1 line 13: 2).
    int inner_iterations = 2;
    // Stop when |E_t - E_{t-w}| <= energy_tolerance |E_{t-w}|, w = energy_window (Sec. 3.3:
    // "does not change by more than 1% over three iterations"). 0 disables the test.
    double energy_tolerance = 0.01;
    int energy_window = 3;

    // ---- T solve (Eq. 9) ----
    LinearSolverOptions linear_solver;

    // ---- execution ----
    int num_threads = 1;
    // Evaluate and record the energy after every block update (costs about one pass over
    // the data per block); when false only the energy per outer iteration is recorded.
    bool trace_blocks = true;

    bool IsValid(std::string* error) const;
  };

  // Runs Alg. 1 from the state in `v` (use energy::InitialVariables for lines 2-5).
  static SolverSummary Minimize(const energy::Problem& problem, const Options& options,
                                energy::Variables* v,
                                const IterationCallback& callback = nullptr);
};

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_ALTERNATING_MINIMIZER_H_
