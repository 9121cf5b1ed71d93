// lpd: the public Options (lpd/denoise.h) resolved into the solvers' DenoiseOptions: the
// preset, then every given parameter in order through its declaration (lpd/parameters.h).
#ifndef LPD_OPTIONS_H_
#define LPD_OPTIONS_H_

#include "lpd/denoise.h"
#include "solvers/denoise_point_set.h"

namespace lpd {

// Throws std::invalid_argument naming the parameter that is unknown, invalid, in conflict
// with another given one, or without effect for the chosen solver.
solvers::DenoiseOptions ResolveOptions(const Options& options);

}  // namespace lpd

#endif  // LPD_OPTIONS_H_
