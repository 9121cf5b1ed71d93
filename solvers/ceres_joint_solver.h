// lpd: the joint solve (the validation solver): Eq. (5) minimized over (H, T, S) at once by
// Ceres, to validate the alternating driver of Alg. 1 on the same energy.
//
// The line processes are eliminated by Eq. (3): each term adds its residuals with the
// Geman-McClure loss (see energy/plane_residuals.h), so Ceres' objective 1/2 sum rho(|f|^2)
// equals Eq. (5) with L and M at their closed forms (Eqs. 6, 7). Each h_i lives on
// ceres::SphereManifold<4>; s_ij are scalar parameter blocks or held at Eq. (8). For the
// Schur solvers, H and S (which never share a residual) are eliminated first, leaving a
// sparse 4n x 4n system in T, the same unknowns the alternating driver's Eq. (9) solves for.
// On return L, M (and S when held at Eq. 8) are at their closed forms for the final state.
#ifndef LPD_SOLVERS_CERES_JOINT_SOLVER_H_
#define LPD_SOLVERS_CERES_JOINT_SOLVER_H_

#include <string>

#include <ceres/types.h>

#include "energy/energy_parameters.h"
#include "energy/problem.h"
#include "energy/variables.h"
#include "solvers/solver_settings.h"
#include "solvers/solver_summary.h"

namespace lpd::solvers {

class CeresJointSolver {
 public:
  struct Options {
    // s_ij as parameter blocks; false holds each at its optimum t_i^T t_j / |t_j|^2 (Eq. 8).
    bool optimize_orientations = true;
    // sparse_schur, iterative_schur, sparse_normal_cholesky or cgnr (the dense solvers would
    // need a dense 4n x 4n matrix).
    ceres::LinearSolverType linear_solver_type = ceres::SPARSE_SCHUR;
    // Levenberg-Marquardt iterations at most, and Ceres' stopping tolerances.
    int max_iterations = 100;
    double function_tolerance = 1e-6;
    double gradient_tolerance = 1e-10;
    double parameter_tolerance = 1e-8;
    // Wall-time budget of the Ceres minimizer (NO_CONVERGENCE when it runs out).
    double max_seconds = 1e6;

    bool IsValid(std::string* error) const;
  };

  // Minimizes Eq. (5) with settings.energy as it is (settings.mu_l_noise_sigmas is the
  // caller's to apply) on settings.num_threads threads, from the state in `v`; every h_i must
  // be non-zero (start from Initialization::kPlaneFit). One IterationRecord per Ceres
  // iteration (from 1), with the energy per term; local/global seconds stay 0.
  static SolverSummary Minimize(const energy::Problem& problem, const SolverSettings& settings,
                                const Options& options, energy::Variables* v,
                                const IterationCallback& callback = nullptr);
};

// "sparse_schur", ... for the supported linear solvers; false for anything else.
bool ParseJointLinearSolver(const std::string& name, ceres::LinearSolverType* type);
std::string JointLinearSolverName(ceres::LinearSolverType type);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_CERES_JOINT_SOLVER_H_
