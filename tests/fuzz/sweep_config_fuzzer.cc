// Fuzz target: the sweep-config parser (YAML, then the grid expansion) on arbitrary bytes.
// Refusing the config with std::runtime_error or std::invalid_argument is the expected
// outcome; a crash, a sanitizer report, a hang or another exception is a finding.
#include <stdexcept>

#include "bytes_file.h"
#include "experiments/sweep/sweep_config.h"
#include "experiments/sweep/sweep_runner.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const BytesFile file(data, size, ".yaml");
  try {
    const lpd::experiments::SweepConfig config = lpd::experiments::LoadSweepConfig(file.path());
    lpd::experiments::ExpandCells(config);
  } catch (const std::runtime_error&) {
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
