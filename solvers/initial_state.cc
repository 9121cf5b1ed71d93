#include "solvers/initial_state.h"

#include "energy/fitting_term.h"
#include "energy/smoothness_term.h"
#include "solvers/local_plane_fit.h"
#include "solvers/parse_by_name.h"

namespace lpd::solvers {

const char* InitializationName(Initialization initialization) {
  return initialization == Initialization::kZero ? "zero" : "plane_fit";
}

bool ParseInitialization(const std::string& name, Initialization* initialization) {
  constexpr Initialization kInitializations[] = {Initialization::kZero,
                                                 Initialization::kPlaneFit};
  return ParseByName(name, kInitializations, InitializationName, initialization);
}

energy::Variables InitialState(const energy::Problem& problem,
                               const energy::EnergyParameters& parameters,
                               Initialization initialization, int num_threads) {
  energy::Variables v = energy::InitialVariables(problem);
  if (initialization == Initialization::kZero) return v;
  UpdateLocalPlanes(problem, parameters, num_threads, &v);  // PCA planes: l = 1, t = 0
  v.t = v.h;
  const energy::SmoothnessTerm smoothness(problem, parameters.lambda, parameters.mu_m,
                                          num_threads);
  smoothness.UpdateOrientations(&v);
  smoothness.UpdateLineProcesses(&v);
  energy::FittingTerm(problem, parameters.mu_l, num_threads).UpdateLineProcesses(&v);
  return v;
}

}  // namespace lpd::solvers
