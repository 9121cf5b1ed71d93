// lpd: the command-line flags of the denoiser (gflags), shared by `denoise` and `bench`,
// mapped into solvers::DenoiseOptions in one place. The parameters' flags are registered
// from their declarations (lpd/parameters.h); only --preset, --solver and --threads are
// declared here.
#ifndef LPD_CLI_DENOISE_FLAGS_H_
#define LPD_CLI_DENOISE_FLAGS_H_

#include <string>
#include <utility>
#include <vector>

#include <gflags/gflags.h>

#include "solvers/denoise_point_set.h"

DECLARE_int32(threads);
DECLARE_string(preset);

namespace lpd::cli {

// DenoiseOptions from the flags; throws std::invalid_argument naming a bad flag. With
// `saved` (the parameters of a saved run, by name), those are the defaults and only the
// flags given on the command line change them.
solvers::DenoiseOptions DenoiseOptionsFromFlags(
    const std::vector<std::pair<std::string, std::string>>* saved = nullptr);

// --help's list of the denoiser's parameters, grouped, each with its default, its data rule
// and the paper's value.
void PrintParameterHelp();

// The parameters given on the command line, as (name, value) in declaration order.
std::vector<std::pair<std::string, std::string>> GivenParameters();

// True if flag `name` was given on the command line.
bool FlagGiven(const char* name);

}  // namespace lpd::cli

#endif  // LPD_CLI_DENOISE_FLAGS_H_
