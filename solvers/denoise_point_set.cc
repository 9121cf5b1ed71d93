#include "solvers/denoise_point_set.h"

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "energy/spatial_order.h"
#include "solvers/parse_by_name.h"

namespace lpd::solvers {
namespace {

// values[r] belongs to input point order[r]; returns them indexed by input point.
template <typename Values>
Values ToInputOrder(const Values& values, const std::vector<int>& order) {
  Values input_ordered(values.size());
  for (size_t r = 0; r < order.size(); ++r) input_ordered[order[r]] = values[r];
  return input_ordered;
}

}  // namespace

const char* SolverName(Solver solver) {
  return solver == Solver::kAlternating ? "alternating" : "ceres";
}

bool ParseSolver(const std::string& name, Solver* solver) {
  constexpr Solver kSolvers[] = {Solver::kAlternating, Solver::kCeres};
  return ParseByName(name, kSolvers, SolverName, solver);
}

Initialization DenoiseOptions::EffectiveInitialization() const {
  if (initialization) return *initialization;
  return solver == Solver::kCeres ? Initialization::kPlaneFit : Initialization::kZero;
}

bool DenoiseOptions::IsValid(std::string* error) const {
  if (!problem.IsValid(error) || !minimizer.IsValid(error) || !final_step.IsValid(error)) {
    return false;
  }
  if (solver == Solver::kCeres) {
    if (!joint.IsValid(error)) return false;
    if (EffectiveInitialization() == Initialization::kZero) {
      *error = "the ceres solver cannot start from initialization zero (h_i = 0 is off the "
               "unit sphere); use plane_fit";
      return false;
    }
  }
  return true;
}

DenoiseResult DenoisePointSet(const energy::PointList& points, const DenoiseOptions& options,
                              const IterationCallback& callback) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument(error);

  DenoiseResult result;
  // The problem holds the points in Morton order (for memory locality); results are mapped
  // back to input order at the end.
  const std::vector<int> order = energy::MortonOrder(points);
  energy::PointList ordered_points(points.size());
  for (size_t r = 0; r < order.size(); ++r) ordered_points[r] = points[order[r]];
  const energy::Problem problem =
      energy::BuildProblem(ordered_points, options.problem, options.minimizer.num_threads);
  result.setup_seconds = std::chrono::duration<double>(Clock::now() - start).count();

  const AlternatingMinimizer::Options& minimizer = options.minimizer;
  energy::Variables v = InitialState(problem, minimizer.energy, options.EffectiveInitialization(),
                                     minimizer.num_threads);
  if (options.solver == Solver::kCeres) {
    CeresJointSolver::Options joint = options.joint;
    joint.num_threads = minimizer.num_threads;
    result.summary = CeresJointSolver::Minimize(problem, minimizer.energy, joint, &v, callback);
  } else {
    result.summary = AlternatingMinimizer::Minimize(problem, minimizer, &v, callback);
  }
  if (!result.summary.IsSolutionUsable()) {
    throw std::runtime_error("minimization failed: " + result.summary.message);
  }

  ProjectOntoTangentPlanes(problem, v, &result.projected, &result.normals);
  result.indicators = ComputeIndicators(problem, v, options.final_step);
  for (auto* values : {&result.projected, &result.normals}) *values = ToInputOrder(*values, order);
  PointIndicators& indicators = result.indicators;
  indicators.outlier_score = ToInputOrder(indicators.outlier_score, order);
  indicators.feature_score = ToInputOrder(indicators.feature_score, order);
  indicators.is_outlier = ToInputOrder(indicators.is_outlier, order);
  indicators.is_feature = ToInputOrder(indicators.is_feature, order);
  const int n = problem.num_points();
  for (int i = 0; i < n; ++i) {
    result.num_outliers += result.indicators.is_outlier[i];
    result.num_features += result.indicators.is_feature[i];
  }
  bool remove = options.final_step.remove_outliers;
  if (remove && result.num_outliers > options.final_step.max_removed_fraction * n) {
    char note[256];
    std::snprintf(note, sizeof(note),
                  "outliers kept: %.1f%% of the points were flagged (more than "
                  "max_removed_fraction = %.0f%%), so mu_l = %.3g is below the noise level",
                  100.0 * result.num_outliers / n,
                  100.0 * options.final_step.max_removed_fraction,
                  options.minimizer.energy.mu_l);
    result.removal_note = note;
    remove = false;
  }
  result.kept.assign(n, 1);
  if (remove) {
    for (int i = 0; i < n; ++i) result.kept[i] = !result.indicators.is_outlier[i];
    result.num_removed = result.num_outliers;
  }
  result.total_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace lpd::solvers
