// Fuzz target: the state-file reader (--resume) on arbitrary bytes. Refusing the file with
// std::runtime_error is the expected outcome; a crash, a sanitizer report, another
// exception, or an accepted state whose contents break its own invariants is a finding.
#include <cstdlib>
#include <stdexcept>

#include "bytes_file.h"
#include "cli/denoise_state_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const BytesFile file(data, size, ".lpds");
  try {
    const lpd::cli::SavedDenoiseRun run = lpd::cli::ReadDenoiseState(file.path());
    const lpd::solvers::DenoiseState& state = run.state;
    const int n = state.problem.num_points();
    if (static_cast<int>(state.order.size()) != n || state.variables.h.rows() != n ||
        !state.variables.h.allFinite() || !(state.problem.frame.scale > 0.0) ||
        state.progress.motion_history.size() != state.progress.energy_history.size()) {
      std::abort();
    }
  } catch (const std::runtime_error&) {
  }
  return 0;
}
