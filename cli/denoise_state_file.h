// lpd: a denoising run saved between iterations and read back (lpd denoise --save-state and
// --resume; the warm restart of Sec. 4.1).
//
// The file holds everything the next iterations depend on, so that a resumed run with the
// same options and thread count is the same bit for bit as an uninterrupted one: the
// denoiser's parameters (as name = value text that reads back to the same doubles), the
// normalization frame, the input order, the normalized points, the points left out of a
// subsample (thinning.h), k and N (M, alpha and beta are rebuilt from them
// deterministically, without a k-NN search), H, T, L, M, S and the minimizer's progress.
// Binary, native doubles, with a byte-order mark; a file from a machine of the other byte
// order, a truncated file or a file of another format is rejected.
#ifndef LPD_CLI_DENOISE_STATE_FILE_H_
#define LPD_CLI_DENOISE_STATE_FILE_H_

#include <string>
#include <utility>
#include <vector>

#include "solvers/denoise_point_set.h"

namespace lpd::cli {

struct SavedDenoiseRun {
  solvers::DenoiseState state;
  // Every parameter of denoise_parameters.h that applies to the solver, by name.
  std::vector<std::pair<std::string, std::string>> parameters;
  int num_threads = 1;  // of the run that saved it
};

// Writes atomically; refuses an existing `path` unless `overwrite`. Throws std::runtime_error.
void WriteDenoiseState(const std::string& path, const solvers::DenoiseState& state,
                       const solvers::DenoiseOptions& options, bool overwrite);

// Throws std::runtime_error "PATH: reason" for a missing, truncated or foreign file.
SavedDenoiseRun ReadDenoiseState(const std::string& path);

}  // namespace lpd::cli

#endif  // LPD_CLI_DENOISE_STATE_FILE_H_
