// lpd: `lpd denoise --tile_points=N`: the tiles of solvers/tiling.h, shared by the ranks of
// `mpirun` (tile_world.h) or run one after another in this process.
//
// Every rank reads the input and plans the same tiles; rank r denoises tiles r, r + R, ...
// (the k-d split balances their sizes) with (cores / R) threads unless --threads is given.
// Rank 0 gathers the outcomes, prints progress (tiles done, points per second, time left) and
// returns the assembled result; the other ranks return without one.
#ifndef LPD_EXPERIMENTS_CLI_TILED_DENOISE_H_
#define LPD_EXPERIMENTS_CLI_TILED_DENOISE_H_

#include <string>

#include "energy/point3.h"
#include "solvers/denoise_point_set.h"
#include "solvers/tiling.h"

namespace lpd::experiments {

struct TiledRun {
  bool is_root = true;
  solvers::DenoiseResult result;  // rank 0: one entry per input point
  std::vector<int> tile_of;        // rank 0: the tile of each input point (from 0)
  std::vector<uint8_t> at_seam;    // rank 0: 1 for the points in another tile's halo
  int tiles = 0;
  int ranks = 1;
  int threads_per_rank = 1;
  int converged_tiles = 0;
  int min_k = 0, max_k = 0;
  int max_iterations = 0;
  long halo_points = 0;           // summed over the tiles
  double seconds = 0.0;
};

// Throws std::invalid_argument (on every rank alike) for tiles too small for a neighbourhood
// or more ranks than tiles; a tile that fails ends every rank with exit code 1, naming it.
TiledRun DenoiseInTiles(const energy::PointList& points, solvers::DenoiseOptions options,
                        const solvers::TilingOptions& tiling, bool threads_given, bool quiet);

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_CLI_TILED_DENOISE_H_
