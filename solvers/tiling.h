// lpd: denoising a cloud tile by tile, for scans too large for one problem or one process.
//
// The cloud is split into spatial tiles with balanced point counts (a k-d split across the
// longest axis into ceil(n / tile_points) tiles of near-equal size). A tile is denoised with
// its halo: every other point within a distance w of the tile's bounding box. Only the
// tile's own points keep their result. A point's result depends on its neighbourhood N(i),
// on its neighbours' planes (their own neighbourhoods, and the smoothing of Eq. (5) over a
// few hops of M), and on the blend of its nearest neighbours' surfaces, so w is a multiple
// of the neighbourhood radius r_k of the tile:
//   w = halo_radii r_k,   r_k = spacing sqrt(k / pi)
// with k and the spacing those the tile's own points get (on the subsample the tile would
// solve, thinning.h): k points fill a disc of radius r_k at that spacing. Every tile runs
// the whole default pipeline (its own k, weights and outlier passes) on its points and halo;
// the command line gives each tile its share of the problem-size budget (tiled_denoise.h).
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

// A k-d split of space into tiles: each inner node sends a point to its low side when its
// coordinate on `axis` is at most `value`; each leaf is a tile.
struct TileTree {
  struct Node {
    int axis = -1;        // -1: a leaf
    double value = 0.0;
    int low = -1, high = -1;
    int tile = -1;        // leaves: the tile number (from 0)
  };
  std::vector<Node> nodes;  // nodes[0] is the root
  int num_tiles = 0;

  int Locate(const energy::Point3& p) const;  // the tile of p
  // As a flat list of numbers (to send between processes) and back.
  std::vector<double> Flatten() const;
  static TileTree Unflatten(const std::vector<double>& values);
};

// Splits `points` (a cloud or a uniform sample of one) across the longest axis until every
// leaf holds at most `capacity` of them, into ceil(n / capacity) leaves of near-equal size.
// Throws std::invalid_argument if capacity < 1.
TileTree PlanTileTree(const energy::PointList& points, int capacity);

// The own points of each tile of PlanTileTree(points, tile_points) (input indices,
// increasing): every point is in exactly one tile.
std::vector<std::vector<int>> PlanTiles(const energy::PointList& points, int tile_points);

// Whether p is within `width` of `box` (the halo test).
inline bool InHalo(const Eigen::AlignedBox3d& box, double width, const energy::Point3& p) {
  return box.exteriorDistance(p) <= width;
}

// The points (input indices, increasing) not in `own` within `width` of its bounding box.
std::vector<int> HaloOf(const energy::PointList& points, const std::vector<int>& own,
                        double width);

// The halo width of a tile (input units): halo_radii r_k with k and spacing chosen on the
// tile's own points (`options.problem.k` when options.choose_k is false).
double HaloWidth(const energy::PointList& own_points, const DenoiseOptions& options,
                 double halo_radii);

// One tile's result, for its own points only (in their order).
struct TileOutcome {
  energy::PointList projected;
  energy::PointList normals;
  PointIndicators indicators;
  std::vector<uint8_t> kept;
  int k = 0;
  int solved_points = 0;          // of the tile and its halo (thinning.h)
  int iterations = 0;
  bool converged = false;
  double seconds = 0.0;
};

// Denoises a tile's own points together with its halo points, with
// `options.settings.num_threads` threads.
TileOutcome DenoiseTile(const energy::PointList& own_points,
                        const energy::PointList& halo_points, const DenoiseOptions& options);

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_TILING_H_
