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
#include <functional>
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

// Where a continuation stands between calls of Alg. 1 (saved with its progress).
struct GncState {
  ContinuedSelectivity mu_l, mu_m;
  int stage_iterations = 0;  // outer iterations done at the current stage
};

// The selectivities Alg. 1's line-process updates use: the targets or, while continuation
// runs, the current stage's values. Alg. 1 asks for them and reports every finished outer
// iteration; nothing else of the continuation reaches its loop.
class SelectivitySchedule {
 public:
  SelectivitySchedule(const GncOptions& options, GncState* state)
      : options_(options), state_(*state) {}

  // mu_l for the L update (Eq. 6). On the first call with mu_l continued, the continuation
  // starts from the residuals whose largest square `max_squared_residual` returns.
  double FittingSelectivity(double target, const std::function<double()>& max_squared_residual);
  // mu_m for the M update (Eq. 7), likewise.
  double SmoothnessSelectivity(double target,
                               const std::function<double()>& max_squared_residual);
  bool AtTargets(double mu_l_target, double mu_m_target) const;
  // After an outer iteration: true if it ran at the targets; otherwise counts it toward the
  // current stage and moves to the next stage when that one is done.
  bool EndIteration(double mu_l_target, double mu_m_target);

 private:
  const GncOptions& options_;
  GncState& state_;
};

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_GRADUATED_NONCONVEXITY_H_
