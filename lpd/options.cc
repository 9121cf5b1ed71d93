#include "lpd/options.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <thread>

#include "lpd/parameters.h"
#include "lpd/presets.h"

namespace lpd {

solvers::DenoiseOptions ResolveOptions(const Options& options) {
  Preset preset;
  if (!ParsePreset(options.preset(), &preset)) {
    throw std::invalid_argument("preset must be default or paper, got '" + options.preset() +
                                "'");
  }
  solvers::DenoiseOptions resolved = PresetOptions(preset);
  if (!solvers::ParseSolver(options.solver, &resolved.solver)) {
    throw std::invalid_argument("solver must be alternating or ceres, got '" + options.solver +
                                "'");
  }
  RefuseConflictingParameters(options.given());
  for (const auto& [name, value] : options.given()) {
    if (!DenoiseParameterApplies(name, resolved.solver)) {
      throw std::invalid_argument("parameter " + name + " has no effect with solver " +
                                  options.solver);
    }
    SetDenoiseParameter(name, value, &resolved);
  }
  if (options.num_threads < 0 || options.num_threads > 1024) {
    throw std::invalid_argument("num_threads must be in [0, 1024], got " +
                                std::to_string(options.num_threads));
  }
  resolved.settings.num_threads =
      options.num_threads > 0 ? options.num_threads
                              : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::string error;
  if (!resolved.IsValid(&error)) throw std::invalid_argument(error);
  return resolved;
}

}  // namespace lpd
