// lpd: runs the cells of a sweep: dataset x noise x method grid point x repetition.
//
// Seeds: repetition r samples its clean points with seed + r and draws its noise with
// seed + 1000003 (r + 1), so every method and noise level of one repetition sees the same
// clean samples and the same underlying random draws (paired comparisons). Cells whose id is
// already in the results are skipped (resume). Cells may run several at once.
#ifndef LPD_EXPERIMENTS_SWEEP_SWEEP_RUNNER_H_
#define LPD_EXPERIMENTS_SWEEP_SWEEP_RUNNER_H_

#include <functional>
#include <string>
#include <vector>

#include "experiments/sweep/sweep_config.h"

namespace lpd::experiments {

struct SweepCell {
  int dataset = 0;
  int noise = -1;  // index into SweepConfig::noise; -1 for file datasets (used as given)
  int method = 0;
  int repetition = 0;
  std::string key;  // every setting of the cell, as text
  std::string id;   // a hash of the key: stable across runs and machines
};

std::vector<SweepCell> ExpandCells(const SweepConfig& config);

// The CSV columns, in order (the JSON records hold these and more).
const std::vector<std::string>& ResultColumns();

struct SweepRunOptions {
  std::string results_directory;  // created if missing
  int num_threads = 1;            // shared among the parallel cells
  std::string git_revision;
  bool dry_run = false;           // list the cells without running them
  // Called with a one-line progress message (from any worker thread, serialized).
  std::function<void(const std::string&)> progress;
};

struct SweepRunSummary {
  int num_cells = 0;
  int num_skipped = 0;  // already in the results
  int num_run = 0;
  int num_failed = 0;   // cells that threw: reported, not recorded (a rerun retries them)
  double seconds = 0.0;
  std::string csv_path;
  std::string jsonl_path;
};

SweepRunSummary RunSweep(const SweepConfig& config, const SweepRunOptions& options);

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_SWEEP_SWEEP_RUNNER_H_
