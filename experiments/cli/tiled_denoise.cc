#include "experiments/cli/tiled_denoise.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <thread>

#include "energy/wall_clock.h"
#include "experiments/cli/tile_world.h"
#include "experiments/io/interruption.h"

namespace lpd::experiments {
namespace {

// The fewest own points a tile may have: its neighbourhood-size probe, or the given k, needs
// that many plus one.
int FewestTilePoints(const solvers::DenoiseOptions& options) {
  const int k = options.choose_k ? std::max(options.neighborhood.probe_k, options.neighborhood.min_k)
                                 : options.problem.k;
  return k + 1;
}

// Rank 0's bookkeeping: the assembled result and the progress line.
class Assembly {
 public:
  Assembly(size_t num_points, int num_tiles, bool quiet, TiledRun* run)
      : num_points_(num_points), num_tiles_(num_tiles), quiet_(quiet), run_(run),
        start_(Clock::now()) {
    solvers::ResizeForTiles(num_points, &run->result);
    run->tile_of.resize(num_points);
    run->at_seam.assign(num_points, 0);
  }

  void Add(int index, const solvers::TileOutcome& tile) {
    solvers::PlaceTile(tile, &run_->result);
    for (int i : tile.own) run_->tile_of[i] = index;
    for (int i : tile.halo) run_->at_seam[i] = 1;
    ++done_;
    points_done_ += tile.own.size();
    run_->converged_tiles += tile.converged;
    run_->min_k = done_ == 1 ? tile.k : std::min(run_->min_k, tile.k);
    run_->max_k = std::max(run_->max_k, tile.k);
    run_->max_iterations = std::max(run_->max_iterations, tile.iterations);
    run_->halo_points += static_cast<long>(tile.halo.size());
    if (quiet_) return;
    const double elapsed = SecondsSince(start_);
    const double rate = points_done_ / std::max(elapsed, 1e-9);
    std::fprintf(stderr,
                 "tile %d/%d done (tile %d: %zu points + %zu halo, k %d, %d iterations, %.1f s); "
                 "%.3g points/s, about %.0f s left\n",
                 done_, num_tiles_, index + 1, tile.own.size(), tile.halo.size(), tile.k,
                 tile.iterations, tile.seconds, rate,
                 (num_points_ - points_done_) / std::max(rate, 1e-9));
  }

  int done() const { return done_; }

 private:
  size_t num_points_;
  int num_tiles_;
  bool quiet_;
  TiledRun* run_;
  Clock::time_point start_;
  int done_ = 0;
  size_t points_done_ = 0;
};

}  // namespace

TiledRun DenoiseInTiles(const energy::PointList& points, solvers::DenoiseOptions options,
                        const solvers::TilingOptions& tiling, bool threads_given, bool quiet) {
  const Clock::time_point start = Clock::now();
  TileWorld world;
  TiledRun run;
  run.is_root = world.is_root();
  run.ranks = world.size();
  const std::vector<std::vector<int>> plan = solvers::PlanTiles(points, tiling.tile_points);
  run.tiles = static_cast<int>(plan.size());
  size_t smallest = points.size();
  for (const std::vector<int>& tile : plan) smallest = std::min(smallest, tile.size());
  if (static_cast<int>(smallest) < FewestTilePoints(options)) {
    world.FailEverywhere("--tile_points=" + std::to_string(tiling.tile_points) +
                         " gives a tile of " + std::to_string(smallest) +
                         " points, fewer than the " + std::to_string(FewestTilePoints(options)) +
                         " a neighbourhood needs");
  }
  if (world.size() > run.tiles) {
    const std::string tiles = std::to_string(run.tiles) + (run.tiles == 1 ? " tile" : " tiles");
    world.FailEverywhere(std::to_string(world.size()) + " ranks for " + tiles +
                         ": start at most as many ranks, or lower --tile_points");
  }
  if (!threads_given && world.size() > 1) {
    const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    options.settings.num_threads = std::max(1, cores / world.size());
  }
  run.threads_per_rank = options.settings.num_threads;
  if (world.is_root() && !quiet) {
    std::fprintf(stderr, "%d tiles of at most %d points on %d process%s x %d thread%s\n",
                 run.tiles, tiling.tile_points, world.size(), world.size() > 1 ? "es" : "",
                 run.threads_per_rank, run.threads_per_rank > 1 ? "s" : "");
  }

  std::unique_ptr<Assembly> assembly;
  if (world.is_root()) assembly = std::make_unique<Assembly>(points.size(), run.tiles, quiet, &run);
  for (int t = world.rank(); t < run.tiles; t += world.size()) {
    solvers::TileOutcome outcome;
    try {
      ThrowIfInterrupted();
      outcome = solvers::DenoiseTile(points, plan[t], options, tiling);
    } catch (const std::exception& error) {
      world.Fail("tile " + std::to_string(t + 1) + " of " + std::to_string(run.tiles) + " (" +
                 std::to_string(plan[t].size()) + " points, rank " +
                 std::to_string(world.rank()) + ") failed: " + error.what());
    }
    if (!world.is_root()) {
      world.Send(t, outcome);
      continue;
    }
    assembly->Add(t, outcome);
    int index = 0;
    solvers::TileOutcome other;
    while (world.Receive(/*wait=*/false, &index, &other)) assembly->Add(index, other);
  }
  if (world.is_root()) {
    int index = 0;
    solvers::TileOutcome other;
    while (assembly->done() < run.tiles && world.Receive(/*wait=*/true, &index, &other)) {
      assembly->Add(index, other);
    }
  }
  run.seconds = SecondsSince(start);
  return run;
}

}  // namespace lpd::experiments
