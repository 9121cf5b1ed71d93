#include "solvers/presets.h"

#include "solvers/parse_by_name.h"

namespace lpd::solvers {

const char* PresetName(Preset preset) { return preset == Preset::kPaper ? "paper" : "default"; }

bool ParsePreset(const std::string& name, Preset* preset) {
  constexpr Preset kPresets[] = {Preset::kDefault, Preset::kPaper};
  return ParseByName(name, kPresets, PresetName, preset);
}

DenoiseOptions PresetOptions(Preset preset) {
  DenoiseOptions options;
  if (preset == Preset::kDefault) return options;
  options.choose_k = false;
  options.problem.k = 20;
  options.weights.fit_balance = 0.0;
  options.weights.smoothing_balance = 0.0;
  options.settings.energy = energy::EnergyParameters();
  options.settings.energy.lambda = 1.0;
  options.settings.energy.eta = 5000.0;
  options.settings.energy.mu_l = 5e-9;
  options.settings.energy.mu_m = 0.13;
  options.settings.mu_l_noise_sigmas = 0.0;
  options.minimizer.max_iterations = 5;
  options.minimizer.inner_iterations = 2;
  options.minimizer.energy_tolerance = 0.01;
  options.minimizer.progress_tolerance = 0.0;
  options.final_step.projection = Projection::kPlane;
  options.final_step.blended_surfaces = 1;
  options.final_step.outlier_fraction = 0.9;
  options.final_step.feature_fraction = 0.7;
  options.final_step.outlier_passes = 1;
  options.final_step.isolation.radius_factor = 0.0;
  return options;
}

}  // namespace lpd::solvers
