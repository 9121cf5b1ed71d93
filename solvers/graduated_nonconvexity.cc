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

}  // namespace lpd::solvers
