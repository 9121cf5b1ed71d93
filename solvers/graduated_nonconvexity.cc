#include "solvers/graduated_nonconvexity.h"

#include <algorithm>
#include <sstream>

#include "solvers/parse_by_name.h"

namespace lpd::solvers {

const char* GncTargetName(GncTarget target) {
  switch (target) {
    case GncTarget::kNone: return "none";
    case GncTarget::kFitting: return "mu_l";
    case GncTarget::kSmoothness: return "mu_m";
    case GncTarget::kBoth: return "both";
  }
  return "none";
}

bool ParseGncTarget(const std::string& name, GncTarget* target) {
  constexpr GncTarget kTargets[] = {GncTarget::kNone, GncTarget::kFitting,
                                    GncTarget::kSmoothness, GncTarget::kBoth};
  return ParseByName(name, kTargets, GncTargetName, target);
}

bool GncOptions::IsValid(std::string* error) const {
  std::ostringstream out;
  if (!(start_ratio == 0.0 || (start_ratio >= 1.0 && std::isfinite(start_ratio)))) {
    out << "gnc_start_ratio must be 0 (convex start) or a finite number >= 1, got "
        << start_ratio;
  } else if (!(factor > 1.0) || !std::isfinite(factor)) {
    out << "gnc_factor must be finite and > 1, got " << factor;
  } else if (stage_iterations < 1) {
    out << "gnc_stage_iters must be >= 1, got " << stage_iterations;
  } else {
    return true;
  }
  *error = out.str();
  return false;
}

void ContinuedSelectivity::Start(const GncOptions& options, double target,
                                 double max_squared_residual) {
  current = options.start_ratio > 0.0 ? options.start_ratio * target
                                      : std::max(target, 3.0 * max_squared_residual);
}

void ContinuedSelectivity::Shrink(const GncOptions& options, double target) {
  if (started()) current = std::max(target, current / options.factor);
}

double SelectivitySchedule::FittingSelectivity(
    double target, const std::function<double()>& max_squared_residual) {
  if (options_.continues_mu_l() && !state_.mu_l.started()) {
    state_.mu_l.Start(options_, target, max_squared_residual());
  }
  return state_.mu_l.Value(target);
}

double SelectivitySchedule::SmoothnessSelectivity(
    double target, const std::function<double()>& max_squared_residual) {
  if (options_.continues_mu_m() && !state_.mu_m.started()) {
    state_.mu_m.Start(options_, target, max_squared_residual());
  }
  return state_.mu_m.Value(target);
}

bool SelectivitySchedule::AtTargets(double mu_l_target, double mu_m_target) const {
  return state_.mu_l.AtTarget(mu_l_target) && state_.mu_m.AtTarget(mu_m_target);
}

bool SelectivitySchedule::EndIteration(double mu_l_target, double mu_m_target) {
  if (AtTargets(mu_l_target, mu_m_target)) return true;
  if (++state_.stage_iterations == options_.stage_iterations) {
    state_.mu_l.Shrink(options_, mu_l_target);
    state_.mu_m.Shrink(options_, mu_m_target);
    state_.stage_iterations = 0;
  }
  return false;
}

}  // namespace lpd::solvers
