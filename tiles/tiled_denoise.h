// lpd: `lpd denoise --tile_points=N`: the tiles of solvers/tiling.h, shared by the ranks of
// `mpirun` (tile_world.h) or run one after another in this process, through the files of
// tile_store.h so that no process holds the whole cloud.
//
// Rank 0 reads the input once into the store, keeping a uniform sample of at most 2^20
// points, and plans the tile tree on the sample (leaves of tile_points x sample / n sample
// points). Rank r denoises tiles r, r + R, ... (with cores / R threads unless --threads is
// given): it gathers the tile's own points, then its halo, from the store, denoises them and
// writes the results back. Rank 0 prints progress (tiles done, points per second, time
// left), then merges the tiles into the output in input order.
#ifndef LPD_TILES_TILED_DENOISE_H_
#define LPD_TILES_TILED_DENOISE_H_

#include <string>

#include "energy/point3.h"
#include "solvers/denoise_point_set.h"
#include "solvers/tiling.h"

namespace lpd::tiles {

struct TiledRun {
  bool is_root = true;
  size_t num_points = 0;
  long kept = 0, outliers = 0, features = 0;  // rank 0: over every tile
  int tiles = 0;
  int ranks = 1;
  int threads_per_rank = 1;
  int converged_tiles = 0;
  int min_k = 0, max_k = 0;
  int max_iterations = 0;
  long halo_points = 0;  // summed over the tiles
  double seconds = 0.0;
};

// Denoises the file `input` (or, when it is empty, `points`) tile by tile and writes the
// result to `output` (rank 0). Throws std::invalid_argument for tiles too small for a
// neighbourhood; more ranks than tiles, a bad input and a tile that fails end every rank
// with exit code 1 and one message (naming the tile, for a failure).
TiledRun DenoiseInTiles(const std::string& input, const energy::PointList& points,
                        solvers::DenoiseOptions options, const solvers::TilingOptions& tiling,
                        const std::string& output, bool overwrite, bool threads_given,
                        bool quiet);

}  // namespace lpd::tiles

#endif  // LPD_TILES_TILED_DENOISE_H_
