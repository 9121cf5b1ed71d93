// lpd: denoising a cloud tile by tile, for scans too large for one problem or one process.
//
// The cloud is split into spatial tiles with balanced point counts (a k-d split at the median
// of the longest axis, down to at most `tile_points` points each). A tile is denoised with
// its halo: every other point within a distance w of the tile's bounding box. Only the
// tile's own points keep their result. A point's result depends on its neighbourhood N(i),
// on its neighbours' planes (their own neighbourhoods, and the smoothing of Eq. (5) over a
// few hops of M), and on the blend of its nearest neighbours' surfaces, so w is a multiple
// of the neighbourhood radius r_k of the tile:
//   w = halo_radii r_k,   r_k = spacing sqrt(k / pi)
// with k and the spacing those the tile's own points get (on the subsample the tile would
// solve, thinning.h): k points fill a disc of radius r_k at that spacing. Every tile runs
// the whole default pipeline (its own k, weights and outlier passes) on its points and halo.
#ifndef LPD_SOLVERS_TILING_H_
#define LPD_SOLVERS_TILING_H_

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "energy/point3.h"
#include "solvers/denoise_point_set.h"

namespace lpd::solvers {

struct TilingOptions {
  int tile_points = 0;      // at most this many own points per tile; 0: no tiling
  // The halo's width in neighbourhood radii r_k (3: docs/method.md, "Tiles").
  double halo_radii = 3.0;
  bool IsValid(std::string* error) const;
};

// The own points of each tile (input indices, increasing), from a k-d split at the median of
// the longest axis until every tile holds at most tile_points. Every point is in exactly one
// tile. Throws std::invalid_argument if tile_points < 1.
std::vector<std::vector<int>> PlanTiles(const energy::PointList& points, int tile_points);

// The axis-aligned bounding box of points[indices].
Eigen::AlignedBox3d BoundingBoxOf(const energy::PointList& points, const std::vector<int>& indices);

// The points (input indices, increasing) not in `own` within `width` of its bounding box.
std::vector<int> HaloOf(const energy::PointList& points, const std::vector<int>& own,
                        double width);

// The halo width of a tile (input units): halo_radii r_k with k and spacing chosen on the
// tile's own points (`options.problem.k` when options.choose_k is false).
double HaloWidth(const energy::PointList& own_points, const DenoiseOptions& options,
                 double halo_radii);

// One tile's result, for its own points only (in the order of `own`).
struct TileOutcome {
  std::vector<int> own;
  energy::PointList projected;
  energy::PointList normals;
  PointIndicators indicators;
  std::vector<uint8_t> kept;
  std::vector<int> halo;          // input indices of the halo points
  int k = 0;
  int solved_points = 0;          // of the tile and its halo (thinning.h)
  int iterations = 0;
  bool converged = false;
  double seconds = 0.0;
};

// Denoises `own` (input indices) with its halo. `options.settings.num_threads` threads.
TileOutcome DenoiseTile(const energy::PointList& points, const std::vector<int>& own,
                        const DenoiseOptions& options, const TilingOptions& tiling);

// Copies a tile's own results into `total` (one entry per input point, sized by the caller
// with ResizeForTiles).
void PlaceTile(const TileOutcome& tile, DenoiseResult* total);
void ResizeForTiles(size_t num_points, DenoiseResult* total);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_TILING_H_
