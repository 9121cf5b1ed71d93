// lpd sweep CONFIG.yaml: run an experiment grid; see configs/README.md for the format.
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include <gflags/gflags.h>

#include "cli/commands.h"
#include "cli/denoise_flags.h"
#include "experiments/sweep/sweep_config.h"
#include "experiments/sweep/sweep_runner.h"
#include "lpd/source_revision.h"

DEFINE_string(results_dir, "",
              "where results.jsonl and results.csv go (default: results/NAME, NAME from the "
              "config); an existing directory is resumed: finished cells are skipped");
DEFINE_bool(dry_run, false, "check the config and list the cells that would run");

namespace lpd::cli {

int RunSweepCommand(const std::vector<std::string>& arguments) {
  if (arguments.size() != 1) throw std::invalid_argument("sweep takes one CONFIG.yaml");
  const experiments::SweepConfig config = experiments::LoadSweepConfig(arguments[0]);
  experiments::SweepRunOptions options;
  options.results_directory = FLAGS_results_dir.empty() ? "results/" + config.name
                                                        : FLAGS_results_dir;
  options.num_threads = FLAGS_threads;
  options.git_revision = SourceRevision();
  options.dry_run = FLAGS_dry_run;
  options.progress = [](const std::string& message) {
    std::fprintf(stderr, "%s\n", message.c_str());
  };
  const experiments::SweepRunSummary summary = experiments::RunSweep(config, options);
  std::printf("sweep %s: %d cells, %d run, %d skipped (done before), %d failed, %.1f s\n",
              config.name.c_str(), summary.num_cells, summary.num_run, summary.num_skipped,
              summary.num_failed, summary.seconds);
  if (!FLAGS_dry_run) std::printf("results: %s\n", summary.csv_path.c_str());
  return summary.num_failed > 0 ? 1 : 0;
}

}  // namespace lpd::cli
