#include "solvers/ceres_joint_solver.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>

#include <ceres/iteration_callback.h>
#include <ceres/ordered_groups.h>
#include <ceres/problem.h>
#include <ceres/solver.h>
#include <ceres/sphere_manifold.h>

#include "energy/energy.h"
#include "energy/fitting_term.h"
#include "energy/smoothness_term.h"
#include "energy/stitching_term.h"
#include "energy/wall_clock.h"
#include "solvers/parse_by_name.h"

namespace lpd::solvers {
namespace {

constexpr ceres::LinearSolverType kSupportedLinearSolvers[] = {
    ceres::SPARSE_SCHUR, ceres::ITERATIVE_SCHUR, ceres::SPARSE_NORMAL_CHOLESKY, ceres::CGNR};

bool UsesSchurComplement(ceres::LinearSolverType type) {
  return type == ceres::SPARSE_SCHUR || type == ceres::ITERATIVE_SCHUR;
}

TerminationType FromCeres(ceres::TerminationType type) {
  switch (type) {
    case ceres::CONVERGENCE:
    case ceres::USER_SUCCESS: return TerminationType::kConvergence;
    case ceres::NO_CONVERGENCE: return TerminationType::kNoConvergence;
    case ceres::USER_FAILURE: return TerminationType::kUserAbort;
    case ceres::FAILURE: return TerminationType::kFailure;
  }
  return TerminationType::kFailure;
}

// Records the energy per term after every Ceres iteration (the parameter blocks are
// updated in place every iteration) and forwards each record to the user's callback. Time
// spent here is left out of elapsed_seconds.
class TraceCallback final : public ceres::IterationCallback {
 public:
  TraceCallback(const energy::Problem& problem, const energy::EnergyParameters& parameters,
                int num_threads, const CeresJointSolver::Options& options,
                Clock::time_point start,
                energy::Variables* v, SolverSummary* summary,
                const solvers::IterationCallback& callback)
      : problem_(problem),
        parameters_(parameters),
        threads_(num_threads),
        options_(options),
        start_(start),
        v_(v),
        summary_(summary),
        callback_(callback) {}

  // Sets L, M (and S when it is held at Eq. 8) to their closed forms, which the Ceres
  // objective implies, and returns Eq. (5) there.
  energy::EnergyBreakdown EliminatedEnergy() const {
    const int threads = threads_;
    energy::FittingTerm(problem_, parameters_.mu_l, threads).UpdateLineProcesses(v_);
    const energy::SmoothnessTerm smoothness(problem_, parameters_.lambda, parameters_.mu_m,
                                            threads);
    if (!options_.optimize_orientations) smoothness.UpdateOrientations(v_);
    smoothness.UpdateLineProcesses(v_);
    return energy::EvaluateEnergy(problem_, parameters_, *v_, threads);
  }

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& step) override {
    const Clock::time_point entered = Clock::now();
    const double elapsed = std::chrono::duration<double>(entered - start_).count() - traced_;
    const energy::EnergyBreakdown energy = EliminatedEnergy();
    traced_ += SecondsSince(entered);
    if (step.iteration == 0) {
      summary_->initial_energy = energy;
      return ceres::SOLVER_CONTINUE;
    }
    IterationRecord record;
    record.iteration = step.iteration;
    record.energy = energy;
    record.seconds = step.iteration_time_in_seconds;
    record.elapsed_seconds = elapsed;
    record.cg_iterations = step.linear_solver_iterations;
    summary_->iterations.push_back(record);
    if (callback_ && !callback_(record)) return ceres::SOLVER_ABORT;
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const energy::Problem& problem_;
  const energy::EnergyParameters& parameters_;
  const int threads_;
  const CeresJointSolver::Options& options_;
  Clock::time_point start_;
  energy::Variables* v_;
  SolverSummary* summary_;
  const solvers::IterationCallback& callback_;
  double traced_ = 0.0;
};

}  // namespace

bool ParseJointLinearSolver(const std::string& name, ceres::LinearSolverType* type) {
  return ParseByName(name, kSupportedLinearSolvers, JointLinearSolverName, type);
}

std::string JointLinearSolverName(ceres::LinearSolverType type) {
  std::string name = ceres::LinearSolverTypeToString(type);
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return name;
}

bool CeresJointSolver::Options::IsValid(std::string* error) const {
  std::ostringstream out;
  const bool supported = std::find(std::begin(kSupportedLinearSolvers),
                                   std::end(kSupportedLinearSolvers),
                                   linear_solver_type) != std::end(kSupportedLinearSolvers);
  if (!supported) {
    out << "ceres_linear_solver must be sparse_schur, iterative_schur, sparse_normal_cholesky "
           "or cgnr, got "
        << JointLinearSolverName(linear_solver_type);
  } else if (max_iterations < 1) {
    out << "ceres_max_iters must be >= 1, got " << max_iterations;
  } else if (!(function_tolerance >= 0.0) || !(gradient_tolerance >= 0.0) ||
             !(parameter_tolerance >= 0.0)) {
    out << "the ceres tolerances must be >= 0";
  } else if (!(max_seconds > 0.0)) {
    out << "ceres_max_seconds must be > 0, got " << max_seconds;
  } else {
    return true;
  }
  *error = out.str();
  return false;
}

SolverSummary CeresJointSolver::Minimize(const energy::Problem& problem,
                                         const SolverSettings& settings,
                                         const Options& options, energy::Variables* v,
                                         const IterationCallback& callback) {
  SolverSummary summary;
  const Clock::time_point start = Clock::now();
  if (!options.IsValid(&summary.message) || !settings.IsValid(&summary.message)) {
    return summary;
  }
  const energy::EnergyParameters& parameters = settings.energy;
  const int n = problem.num_points();
  for (int i = 0; i < n; ++i) {
    if (!(v->h.row(i).norm() > 0.0) || !v->h.row(i).allFinite()) {
      summary.message = "h_" + std::to_string(i) +
                        " is zero or not finite; the joint solve starts from plane_fit";
      return summary;
    }
  }

  const int threads = settings.num_threads;
  ceres::Problem::Options problem_options;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem joint(problem_options);
  energy::FittingTerm(problem, parameters.mu_l, threads).AddResiduals(v, &joint);
  energy::SmoothnessTerm(problem, parameters.lambda, parameters.mu_m, threads)
      .AddResiduals(v, options.optimize_orientations, &joint);
  energy::StitchingTerm(problem, parameters.eta, threads).AddResiduals(v, &joint);
  ceres::SphereManifold<4> sphere;
  for (int i = 0; i < n; ++i) joint.SetManifold(v->h.data() + 4 * i, &sphere);

  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = options.linear_solver_type;
  if (UsesSchurComplement(options.linear_solver_type)) {
    auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();
    for (int i = 0; i < n; ++i) {
      ordering->AddElementToGroup(v->h.data() + 4 * i, 0);
      ordering->AddElementToGroup(v->t.data() + 4 * i, 1);
    }
    if (options.optimize_orientations) {
      for (int p = 0; p < problem.graph.num_pairs(); ++p) {
        ordering->AddElementToGroup(v->s.data() + p, 0);
      }
    }
    solver_options.linear_solver_ordering = ordering;
  }
  solver_options.max_num_iterations = options.max_iterations;
  solver_options.function_tolerance = options.function_tolerance;
  solver_options.gradient_tolerance = options.gradient_tolerance;
  solver_options.parameter_tolerance = options.parameter_tolerance;
  solver_options.max_solver_time_in_seconds = options.max_seconds;
  solver_options.num_threads = threads;
  solver_options.logging_type = ceres::SILENT;
  solver_options.update_state_every_iteration = true;
  TraceCallback trace(problem, parameters, threads, options, start, v, &summary, callback);
  solver_options.callbacks.push_back(&trace);

  ceres::Solver::Summary ceres_summary;
  ceres::Solve(solver_options, &joint, &ceres_summary);

  summary.final_energy = trace.EliminatedEnergy();
  summary.termination = FromCeres(ceres_summary.termination_type);
  summary.message = ceres_summary.message;
  summary.num_iterations = static_cast<int>(summary.iterations.size());
  if (!std::isfinite(summary.final_energy.total())) {
    summary.termination = TerminationType::kFailure;
    summary.message = "the energy became non-finite";
  }
  summary.total_seconds = SecondsSince(start);
  return summary;
}

}  // namespace lpd::solvers
