// lpd bench INPUT [flags]: wall time per step of Alg. 1 and peak memory, end to end
// (read, k-NN, optimize, project). Runs all --max_iters iterations (no early stop), one
// pass without isolation test, and does not evaluate the energy between blocks, so the
// figures are the method's own cost.
#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include <gflags/gflags.h>

#include "energy/data_scaled_weights.h"
#include "energy/term_balance.h"
#include "energy/wall_clock.h"
#include "cli/commands.h"
#include "cli/denoise_flags.h"
#include "io/peak_memory.h"
#include "io/point_cloud_io.h"
#include "solvers/denoise_point_set.h"

namespace lpd::cli {
namespace {

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

int RunBenchCommand(const std::vector<std::string>& arguments) {
  if (arguments.size() != 1) throw std::invalid_argument("bench takes one INPUT file");
  const Clock::time_point start = Clock::now();
  solvers::DenoiseOptions options = DenoiseOptionsFromFlags();
  options.minimizer.energy_tolerance = 0.0;
  options.minimizer.progress_tolerance = 0.0;
  options.minimizer.motion_tolerance = 0.0;
  options.minimizer.trace_blocks = false;
  // One pass and no isolation test: the figures are those of one minimization.
  options.final_step.outlier_passes = 1;
  options.final_step.isolation.radius_factor = 0.0;
  const energy::PointList points = io::ReadPoints(arguments[0]);
  const double read_seconds = SecondsSince(start);
  double balance = 0.0;
  solvers::DenoiseHooks hooks;
  hooks.on_started = [&options, &balance](const solvers::DenoiseState& state) {
    balance = energy::MedianSmoothnessToStitchingRatio(
        state.problem,
        energy::ScaleWeightsToData(state.problem, options.settings.energy, options.weights));
  };
  const solvers::DenoiseResult result = solvers::DenoisePointSet(points, options, hooks);
  const double total_seconds = SecondsSince(start);

  std::printf("input %s: n = %zu, k = %d, threads = %d, %d outer x %d inner iterations\n",
              arguments[0].c_str(), points.size(), result.neighborhood.k,
              options.settings.num_threads, options.minimizer.max_iterations,
              options.minimizer.inner_iterations);
  std::printf("read %.3f s, k-NN graph and weights %.3f s\n", read_seconds,
              result.setup_seconds);
  // How close the T system is to a graph Laplacian (energy/term_balance.h).
  std::printf("smoothness / stitching share of K's diagonal: median %.3g\n", balance);
  std::printf("iter  local(H,L) s  global(T,M,S) s  iteration s  cg iterations\n");
  std::vector<double> local, global, whole;
  for (const solvers::IterationRecord& r : result.summary.iterations) {
    std::printf("%4d  %12.3f  %15.3f  %11.3f  %13d\n", r.iteration, r.local_seconds,
                r.global_seconds, r.seconds, r.cg_iterations);
    local.push_back(r.local_seconds);
    global.push_back(r.global_seconds);
    whole.push_back(r.seconds);
  }
  std::printf("median per iteration: local %.3f s, global %.3f s, whole %.3f s\n",
              Median(local), Median(global), Median(whole));
  std::printf("stages (s):");
  for (const auto& [stage, seconds] : result.stage_times.stages()) {
    std::printf(" %s %.3f;", stage.c_str(), seconds);
  }
  std::printf("\n");
  const long long peak = io::PeakResidentBytes();
  std::printf("end to end %.2f s, peak resident memory %.1f MB (%.0f bytes per point)\n",
              total_seconds, peak / 1e6, static_cast<double>(peak) / points.size());
  return 0;
}

}  // namespace lpd::cli
