// lpd: the files of a tiled run (tiled_denoise.h), so that no process holds the whole cloud.
//
// In a fresh directory under $TMPDIR (or /tmp):
//   points.bin   the input's coordinates as raw doubles, written once by rank 0 while it
//                reads the input, then scanned in chunks: twice per tile (its own points,
//                then its halo);
//   tile_T.bin   tile T's results for its own points, in input order.
// Rank 0 merges the tile files into the output in input order: it scans points.bin, finds
// each point's tile with the tile tree and takes the next result of that tile's file. The
// directory is removed when rank 0's store is destroyed (also after an error; a run ended by
// MPI_Abort or a signal can leave it behind).
#ifndef LPD_TILES_TILE_STORE_H_
#define LPD_TILES_TILE_STORE_H_

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "energy/point3.h"
#include "solvers/tiling.h"

namespace lpd::tiles {

// What rank 0 needs of a finished tile to merge it.
struct TileSummary {
  int tile = 0;
  long own_points = 0, kept = 0, outliers = 0, features = 0, halo_points = 0;
  int k = 0, solved_points = 0, iterations = 0;
  bool converged = false;
  double seconds = 0.0;
  Eigen::AlignedBox3d box;  // of its own points
  double halo_width = 0.0;

  std::vector<double> Flatten() const;
  static TileSummary Unflatten(const std::vector<double>& values);
};

class TileStore {
 public:
  // Rank 0 creates the directory (and owns it); the other ranks open the one rank 0 names.
  static std::string CreateDirectory();
  TileStore(std::string directory, bool owner);
  ~TileStore();
  TileStore(const TileStore&) = delete;
  TileStore& operator=(const TileStore&) = delete;
  const std::string& directory() const { return directory_; }

  // Rank 0: writes the points of the file `input` (or `points`) to points.bin and returns
  // their number; `sample` receives a seeded uniform sample of at most `sample_size` of them.
  size_t Spool(const std::string& input, size_t sample_size, energy::PointList* sample);
  size_t Spool(const energy::PointList& points, size_t sample_size, energy::PointList* sample);

  // Calls visit(index, p) for every point of points.bin in input order.
  void Scan(const std::function<void(uint32_t, const energy::Point3&)>& visit) const;

  // Writes tile `tile`'s results for its own points `own` (input indices, increasing).
  void WriteTile(int tile, const std::vector<uint32_t>& own,
                 const solvers::TileOutcome& outcome) const;

  // Rank 0, once every tile is written: the kept points in input order to `output` (.ply with
  // normals, the attributes of the file `input` when one was spooled, then outlier,
  // outlier_score, feature, feature_score, seam, source_index and tile; or .xyz). The input
  // is read again point by point for its attributes (colours, intensities, ...; an attribute
  // named as one of those fields is written input_NAME); a point that differs from the
  // spooled one ends the merge with an error. A point is at a seam when it lies in the halo
  // of a tile other than its own.
  void Merge(const solvers::TileTree& tree, const std::vector<TileSummary>& tiles,
             const std::string& input, const std::string& output, bool overwrite) const;

 private:
  std::string directory_;
  bool owner_;
  // Slots of the interruption module's watchdog (io/interruption.h) for the directory and
  // its files, so that a forced exit after a signal removes them too.
  mutable std::vector<int> slots_;
};

}  // namespace lpd::tiles

#endif  // LPD_TILES_TILE_STORE_H_
