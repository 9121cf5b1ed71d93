// lpd: the command-line flags of the denoiser (gflags), shared by `denoise` and `bench`,
// mapped into solvers::DenoiseOptions in one place.
#ifndef LPD_EXPERIMENTS_DENOISE_FLAGS_H_
#define LPD_EXPERIMENTS_DENOISE_FLAGS_H_

#include <gflags/gflags.h>

#include "solvers/denoise_point_set.h"

DECLARE_int32(threads);

namespace lpd::experiments {

// DenoiseOptions from the flags; throws std::invalid_argument naming a bad flag.
solvers::DenoiseOptions DenoiseOptionsFromFlags();

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_DENOISE_FLAGS_H_
