// lpd: experiment sweeps described in YAML (see configs/README.md for the format).
//
// A sweep crosses datasets (procedural shapes, meshes, or noisy files with an optional ground
// truth) with noise settings and method parameter grids, repeated with different seeds.
// Loading checks everything up front: malformed YAML, unknown keys, bad values, missing files
// and unknown method parameters are reported as "FILE:LINE: reason".
#ifndef LPD_EXPERIMENTS_SWEEP_SWEEP_CONFIG_H_
#define LPD_EXPERIMENTS_SWEEP_SWEEP_CONFIG_H_

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "experiments/baselines/surface_reconstruction.h"
#include "experiments/shapes/noise.h"

namespace lpd::experiments {

// A scalar from the config, as written, with its line (1-based) for error messages.
struct ConfigValue {
  std::string text;
  int line = 0;
};
using ParameterSet = std::map<std::string, ConfigValue>;

struct DatasetConfig {
  std::string name;          // label in the results
  std::string shape;         // procedural shape, "NAME[:key=value,...]"
  std::string mesh;          // or a triangle mesh, sampled uniformly by area
  std::string file;          // or a noisy point file, used as given
  std::string ground_truth;  // for `file`: optional ground-truth source (ground_truth_source.h)
  int points = 25000;        // samples drawn from `shape` or `mesh`
  // Poisson-disk samples (poisson_disk_sampling.h) instead of area-uniform random ones.
  bool poisson_disk = false;
  int line = 0;
};

struct MethodConfig {
  std::string method;        // a name of MethodNames() (sweep_methods.h)
  ParameterSet parameters;   // one point of the method's grid
};

struct SweepConfig {
  std::string path;
  std::string name;
  int repetitions = 1;
  uint64_t seed = 1;
  int parallel_cells = 1;
  int threads_per_cell = 0;  // 0: the available threads divided among the parallel cells
  int ground_truth_samples = 200000;
  double feature_band = 0.01;  // fraction of the diagonal around sharp edges
  // Write every cell's input (with its indicators) and output (with its distance to the
  // ground truth) as PLY to RESULTS/clouds/, for renderings (paper_figures/render_clouds.py).
  bool save_clouds = false;
  // Surfaces reconstructed from every cell's output (surface_reconstruction.h), written to
  // RESULTS/meshes/ID_METHOD.off for renderings (paper_figures/render_meshes.py).
  std::vector<Reconstruction> reconstructions;
  std::vector<DatasetConfig> datasets;
  std::vector<ParameterSet> noise;     // the expanded noise grid (one empty set if none)
  std::vector<MethodConfig> methods;   // the expanded method grids
};

// Throws std::runtime_error("FILE:LINE: reason") on any problem.
SweepConfig LoadSweepConfig(const std::string& path);

// NoiseOptions from one noise grid point (keys: model, sigma, scale, outliers, outlier_ratio,
// outlier_margin); the seed is left at its default. Throws "FILE:LINE: reason".
NoiseOptions ToNoiseOptions(const ParameterSet& noise, const std::string& config_path);

// "key=value,key=value" in key order (for cell keys and result columns).
std::string Describe(const ParameterSet& parameters);

// Replaces "${LPD_DATA}" by the LPD_DATA environment variable, or by the shared data directory
// next to the source tree when it is unset.
std::string ExpandDataPath(const std::string& path);

// How many noise settings `dataset` runs with: the whole noise grid when it is generated,
// one ("as given") when it is read from a file.
int NumNoiseSettings(const SweepConfig& config, const DatasetConfig& dataset);

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_SWEEP_SWEEP_CONFIG_H_
