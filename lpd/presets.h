// lpd: named parameter sets for a whole denoising run.
//
//   kDefault  what `lpd denoise` runs: k from the noise and spacing (neighborhood_size.h),
//             eta and lambda from the data (energy/data_scaled_weights.h), mu_l from a
//             robust noise estimate, run to convergence, sphere projection, a second pass
//             without the outliers when the first removed more than 5% of the points, the
//             indicator thresholds 65% / 30%. Every weight is dimensionless, so one set holds
//             across scales and noise levels. These are the defaults of DenoiseOptions.
//   kPaper    the paper's literal setting (Table 2, Alg. 1, Sec. 3.4), for reproduction:
//             the default with every parameter's paper value (lpd/parameters.cc) applied:
//             k = 20, lambda = 1, eta = 5000, mu_l = 5e-9, mu_m = 0.13, Alg. 1 from
//             H = T = 0, 5 outer iterations of 2 inner passes, stop at a 1% energy change
//             over three iterations, projection onto t_i.
#ifndef LPD_PRESETS_H_
#define LPD_PRESETS_H_

#include <string>

#include "solvers/denoise_point_set.h"

namespace lpd {

enum class Preset { kDefault, kPaper };
const char* PresetName(Preset preset);  // "default", "paper"
bool ParsePreset(const std::string& name, Preset* preset);

solvers::DenoiseOptions PresetOptions(Preset preset);

}  // namespace lpd

#endif  // LPD_PRESETS_H_
