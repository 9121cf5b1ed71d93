// lpd: graduated non-convexity (GNC) for the selectivities mu_l and mu_m (Sec. 2.2, Sec. 5).
//
// The Geman-McClure cost rho_mu(x) = x^2 / (1 + x^2 / mu) is convex in x while x^2 < mu / 3.
// Continuation starts each continued mu where rho_mu is convex over every current residual
// (mu_0 = 3 max x^2, never below the target) or at a given multiple of the target, and
// divides it by `factor` after every `stage_iterations` outer iterations of Alg. 1 until it
// reaches the target (Blake and Zisserman's GNC; the schedule of Yang et al. 2020).
#ifndef LPD_SOLVERS_GRADUATED_NONCONVEXITY_H_
#define LPD_SOLVERS_GRADUATED_NONCONVEXITY_H_

#include <cmath>
#include <string>

namespace lpd::solvers {

// Which selectivities are continued.
enum class GncTarget { kNone, kFitting, kSmoothness, kBoth };
const char* GncTargetName(GncTarget target);  // "none", "mu_l", "mu_m", "both"
bool ParseGncTarget(const std::string& name, GncTarget* target);

struct GncOptions {
  GncTarget target = GncTarget::kNone;
  // mu at the first stage as a multiple of its target; 0 starts where rho_mu is convex over
  // the residuals at that point (3 max x^2).
  double start_ratio = 0.0;
  // mu_{stage + 1} = max(target, mu_stage / factor) (Yang et al. use 1.4).
  double factor = 1.4;
  int stage_iterations = 1;  // outer iterations per stage

  bool continues_mu_l() const { return target == GncTarget::kFitting || target == GncTarget::kBoth; }
  bool continues_mu_m() const {
    return target == GncTarget::kSmoothness || target == GncTarget::kBoth;
  }
  bool IsValid(std::string* error) const;
};

// One continued selectivity. NaN `current` means not started yet.
struct ContinuedSelectivity {
  double current = NAN;

  bool started() const { return !std::isnan(current); }
  // Starts at `options.start_ratio` x target or, when that is 0, at the convex start for
  // residuals whose largest square is `max_squared_residual`.
  void Start(const GncOptions& options, double target, double max_squared_residual);
  // Moves to the next stage: current = max(target, current / factor).
  void Shrink(const GncOptions& options, double target);
  // The mu to use now: `current` once started, else the target.
  double Value(double target) const { return started() ? current : target; }
  bool AtTarget(double target) const { return !started() || current <= target; }
};

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_GRADUATED_NONCONVEXITY_H_
