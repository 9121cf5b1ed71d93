#include "lpd/presets.h"

#include "lpd/parameters.h"
#include "solvers/parse_by_name.h"

namespace lpd {

const char* PresetName(Preset preset) { return preset == Preset::kPaper ? "paper" : "default"; }

bool ParsePreset(const std::string& name, Preset* preset) {
  constexpr Preset kPresets[] = {Preset::kDefault, Preset::kPaper};
  return solvers::ParseByName(name, kPresets, PresetName, preset);
}

solvers::DenoiseOptions PresetOptions(Preset preset) {
  solvers::DenoiseOptions options;
  if (preset == Preset::kDefault) return options;
  for (const ParameterInfo& parameter : DenoiseParameters()) {
    if (!parameter.paper_value.empty()) {
      SetDenoiseParameter(parameter.name, parameter.paper_value, &options);
    }
  }
  // Alg. 1 from H = T = 0 as published; not a paper value of `initialization`, which would
  // also apply to the joint solve, which cannot start there.
  options.alternating_start = solvers::Initialization::kZero;
  return options;
}

}  // namespace lpd
