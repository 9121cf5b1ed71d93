// lpd: the methods a sweep can run, by name, with their parameters given as text.
//
//   none   the noisy input unchanged (the "input" row of a table)
//   lpd    the paper's method (DenoisePointSet, Alg. 1); parameters as in denoise_parameters.h
//   ceres  the same energy minimized jointly by Ceres (the validation solver), followed by
//          the same final step; the parameters that apply to the joint solve
//   bilateral  CGAL bilateral smoothing with estimated normals (cgal_baselines.h):
//              k=60, sharpness_angle=25 (degrees), iterations=3, normals=pca|jet
//   jet        CGAL jet smoothing: k=32, iterations=1
//   wlop       CGAL WLOP resampling: select_percentage=20, radius_spacings=8, iterations=35
// The baselines run on one thread (Debian's CGAL has no TBB).
#ifndef LPD_EXPERIMENTS_SWEEP_SWEEP_METHODS_H_
#define LPD_EXPERIMENTS_SWEEP_SWEEP_METHODS_H_

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "energy/energy.h"
#include "energy/point3.h"
#include "experiments/sweep/sweep_config.h"

namespace lpd::experiments {

struct MethodRun {
  energy::PointList output;            // the denoised points (removed outliers left out)
  // Per input point; empty when the method does not detect them.
  std::vector<uint8_t> outlier_flags;
  std::vector<uint8_t> feature_flags;
  int iterations = 0;
  double initial_energy = NAN;
  double final_energy = NAN;
  // (elapsed seconds, total energy of Eq. 5) at the start and after every iteration.
  std::vector<std::pair<double, double>> energy_trace;
  // The energy per term after every iteration.
  std::vector<energy::EnergyBreakdown> energy_terms;
  double mu_l = NAN;                   // the mu_l used (scale-aware or as given)
  double seconds = 0.0;                // whole method, setup included
  double setup_seconds = 0.0;          // normalization and k-NN graph
  double local_seconds = 0.0;          // per outer iteration, mean
  double global_seconds = 0.0;         // per outer iteration, mean
  std::string termination;
  std::string note;
};

const std::vector<std::string>& MethodNames();

// Every parameter a method knows, with its effective value for `parameters` (defaults filled
// in). Throws std::invalid_argument for an unknown method, parameter or value.
std::vector<std::pair<std::string, std::string>> EffectiveParameters(
    const MethodConfig& method);

MethodRun RunMethod(const MethodConfig& method, const energy::PointList& input, int num_threads);

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_SWEEP_SWEEP_METHODS_H_
