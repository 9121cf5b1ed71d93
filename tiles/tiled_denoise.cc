#include "tiles/tiled_denoise.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <thread>

#include "energy/wall_clock.h"
#include "tiles/tile_store.h"
#include "tiles/tile_world.h"
#include "io/interruption.h"

namespace lpd::tiles {
namespace {

constexpr size_t kSampleSize = 1 << 20;  // points the tile tree is planned on

// The fewest own points a tile may have: its neighbourhood-size probe, or the given k, needs
// that many plus one.
int FewestTilePoints(const solvers::DenoiseOptions& options) {
  const int k = options.choose_k
                    ? std::max(options.neighborhood.probe_k, options.neighborhood.min_k)
                    : options.problem.k;
  return k + 1;
}

// Rank 0's tally of finished tiles and the progress line.
class Progress {
 public:
  Progress(size_t num_points, int num_tiles, bool quiet, TiledRun* run)
      : num_points_(num_points), num_tiles_(num_tiles), quiet_(quiet), run_(run),
        start_(Clock::now()) {}

  void Add(const TileSummary& tile) {
    summaries_.push_back(tile);
    points_done_ += tile.own_points;
    run_->kept += tile.kept;
    run_->outliers += tile.outliers;
    run_->features += tile.features;
    run_->converged_tiles += tile.converged;
    run_->min_k = summaries_.size() == 1 ? tile.k : std::min(run_->min_k, tile.k);
    run_->max_k = std::max(run_->max_k, tile.k);
    run_->max_iterations = std::max(run_->max_iterations, tile.iterations);
    run_->halo_points += tile.halo_points;
    if (quiet_) return;
    const double rate = points_done_ / std::max(SecondsSince(start_), 1e-9);
    std::fprintf(stderr,
                 "tile %zu/%d done (tile %d: %ld points + %ld halo, k %d, %d iterations, "
                 "%.1f s); %.3g points/s, about %.0f s left\n",
                 summaries_.size(), num_tiles_, tile.tile + 1, tile.own_points,
                 tile.halo_points, tile.k, tile.iterations, tile.seconds, rate,
                 (num_points_ - points_done_) / std::max(rate, 1e-9));
  }

  int done() const { return static_cast<int>(summaries_.size()); }
  const std::vector<TileSummary>& summaries() const { return summaries_; }

 private:
  size_t num_points_;
  int num_tiles_;
  bool quiet_;
  TiledRun* run_;
  Clock::time_point start_;
  size_t points_done_ = 0;
  std::vector<TileSummary> summaries_;
};

// The options of a problem of `points` of the run's `num_points`: its share of the run's
// problem-size budget, so that past the budget a tile solves the same density of points at
// the same k as the untiled run would (thinning.h); the smallest budget allowed at least.
solvers::DenoiseOptions ShareOfBudget(solvers::DenoiseOptions options, size_t points,
                                      size_t num_points) {
  double& budget = options.neighborhood.max_problem_size;
  budget = std::max(solvers::NeighborhoodSizeOptions::kSmallestProblemSize,
                    budget * static_cast<double>(points) / static_cast<double>(num_points));
  return options;
}

// Tile `t`: its own points and halo from the store, denoised; the results go to the store.
TileSummary RunTile(const TileStore& store, const solvers::TileTree& tree, int t,
                    size_t num_points, const solvers::DenoiseOptions& options,
                    const solvers::TilingOptions& tiling) {
  std::vector<uint32_t> own;
  energy::PointList own_points;
  store.Scan([&](uint32_t index, const energy::Point3& p) {
    if (tree.Locate(p) != t) return;
    own.push_back(index);
    own_points.push_back(p);
  });
  TileSummary summary;
  summary.tile = t;
  if (own.empty()) {  // ties at a split can empty a tile of the sample's plan
    store.WriteTile(t, own, solvers::TileOutcome());
    return summary;
  }
  if (static_cast<int>(own.size()) < FewestTilePoints(options)) {
    throw std::invalid_argument("it holds " + std::to_string(own.size()) +
                                " points, fewer than the " +
                                std::to_string(FewestTilePoints(options)) +
                                " a neighbourhood needs (raise --tile_points)");
  }
  for (const energy::Point3& p : own_points) summary.box.extend(p);
  summary.halo_width = solvers::HaloWidth(
      own_points, ShareOfBudget(options, own_points.size(), num_points), tiling.halo_radii);
  energy::PointList halo_points;
  store.Scan([&](uint32_t, const energy::Point3& p) {
    if (solvers::InHalo(summary.box, summary.halo_width, p) && tree.Locate(p) != t) {
      halo_points.push_back(p);
    }
  });
  const solvers::TileOutcome outcome = solvers::DenoiseTile(
      own_points, halo_points,
      ShareOfBudget(options, own_points.size() + halo_points.size(), num_points));
  store.WriteTile(t, own, outcome);
  summary.own_points = static_cast<long>(own.size());
  summary.halo_points = static_cast<long>(halo_points.size());
  for (size_t a = 0; a < own.size(); ++a) {
    summary.kept += outcome.kept[a];
    summary.outliers += outcome.indicators.is_outlier[a];
    summary.features += outcome.indicators.is_feature[a];
  }
  summary.k = outcome.k;
  summary.solved_points = outcome.solved_points;
  summary.iterations = outcome.iterations;
  summary.converged = outcome.converged;
  summary.seconds = outcome.seconds;
  return summary;
}

// "1 tile", "2 tiles"; `plural` for nouns not made with an s.
std::string Count(int count, const std::string& noun, const std::string& plural = "") {
  return std::to_string(count) + " " +
         (count == 1 ? noun : plural.empty() ? noun + "s" : plural);
}

}  // namespace

TiledRun DenoiseInTiles(const std::string& input, const energy::PointList& points,
                        solvers::DenoiseOptions options, const solvers::TilingOptions& tiling,
                        const std::string& output, bool overwrite, bool threads_given,
                        bool quiet) {
  if (tiling.tile_points < FewestTilePoints(options)) {
    throw std::invalid_argument("--tile_points=" + std::to_string(tiling.tile_points) +
                                " is fewer than the " +
                                std::to_string(FewestTilePoints(options)) +
                                " points a neighbourhood needs");
  }
  const Clock::time_point start = Clock::now();
  TileWorld world;
  TiledRun run;
  run.is_root = world.is_root();
  run.ranks = world.size();

  // Rank 0 reads the input into the store and plans; the plan goes to every rank.
  std::unique_ptr<TileStore> store;
  std::vector<double> plan;  // directory name, n, then the flattened tile tree
  if (world.is_root()) {
    try {
      store = std::make_unique<TileStore>(TileStore::CreateDirectory(), /*owner=*/true);
      energy::PointList sample;
      run.num_points = input.empty() ? store->Spool(points, kSampleSize, &sample)
                                     : store->Spool(input, kSampleSize, &sample);
      const int capacity = std::max<int>(
          1, static_cast<int>(std::lround(static_cast<double>(tiling.tile_points) *
                                          sample.size() / run.num_points)));
      const std::vector<double> tree = solvers::PlanTileTree(sample, capacity).Flatten();
      plan.assign(store->directory().begin(), store->directory().end());
      plan.insert(plan.begin(), static_cast<double>(plan.size()));
      plan.push_back(static_cast<double>(run.num_points));
      plan.insert(plan.end(), tree.begin(), tree.end());
    } catch (const io::Interrupted&) {
      throw;  // a signal: the command reports it, with its exit code (interruption.h)
    } catch (const std::exception& error) {
      store.reset();
      world.Fail(error.what());
    }
  }
  world.Broadcast(&plan);
  const size_t name_length = static_cast<size_t>(plan[0]);
  if (!world.is_root()) {
    const std::string directory(plan.begin() + 1, plan.begin() + 1 + name_length);
    store = std::make_unique<TileStore>(directory, /*owner=*/false);
  }
  run.num_points = static_cast<size_t>(plan[1 + name_length]);
  // Every tile blends as many surfaces as the whole cloud would.
  options.final_step = options.final_step.ForCloudOf(run.num_points);
  const solvers::TileTree tree = solvers::TileTree::Unflatten(
      std::vector<double>(plan.begin() + 2 + name_length, plan.end()));
  run.tiles = tree.num_tiles;
  if (world.size() > run.tiles) {
    if (world.is_root()) store.reset();
    world.FailEverywhere(Count(world.size(), "rank") + " for " + Count(run.tiles, "tile") +
                         ": start at most as many ranks, or lower --tile_points");
  }
  if (!threads_given && world.size() > 1) {
    const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    options.settings.num_threads = std::max(1, cores / world.size());
  }
  run.threads_per_rank = options.settings.num_threads;
  if (world.is_root() && !quiet) {
    std::fprintf(stderr, "%zu points in %s of about %d points on %s x %s\n", run.num_points,
                 Count(run.tiles, "tile").c_str(), tiling.tile_points,
                 Count(world.size(), "process", "processes").c_str(),
                 Count(run.threads_per_rank, "thread").c_str());
  }

  Progress progress(run.num_points, run.tiles, quiet, &run);
  std::vector<double> message;
  for (int t = world.rank(); t < run.tiles; t += world.size()) {
    TileSummary summary;
    try {
      io::ThrowIfInterrupted();
      summary = RunTile(*store, tree, t, run.num_points, options, tiling);
    } catch (const io::Interrupted&) {
      throw;  // a signal: the command reports it, with its exit code (interruption.h)
    } catch (const std::exception& error) {
      if (world.is_root()) store.reset();
      world.Fail("tile " + std::to_string(t + 1) + " of " + std::to_string(run.tiles) +
                 " (rank " + std::to_string(world.rank()) + ") failed: " + error.what());
    }
    if (!world.is_root()) {
      world.Send(summary.Flatten());
      continue;
    }
    progress.Add(summary);
    try {
      while (world.Receive(/*wait=*/false, &message)) {
        progress.Add(TileSummary::Unflatten(message));
      }
    } catch (const TileWorld::RankFailed&) {
      store.reset();
      world.Abort();
    }
  }
  if (!world.is_root()) return run;
  try {
    while (progress.done() < run.tiles && world.Receive(/*wait=*/true, &message)) {
      progress.Add(TileSummary::Unflatten(message));
    }
  } catch (const TileWorld::RankFailed&) {
    store.reset();
    world.Abort();
  }
  io::ThrowIfInterrupted();
  if (!output.empty()) store->Merge(tree, progress.summaries(), input, output, overwrite);
  run.seconds = SecondsSince(start);
  return run;
}

}  // namespace lpd::tiles
