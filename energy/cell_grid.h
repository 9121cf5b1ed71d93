// lpd: a uniform grid of cubic cells over a point list, for gathering the points within a
// radius of a query.
//
// The k-nearest searches of the probe, the graph and the final steps gather every point within
// a guessed radius and sort them (nearest_neighbors.h). On a surface sample, the points within
// a few cells of a query lie in a handful of contiguous runs of a list sorted by cell (z, y,
// x), and scanning those runs without branching is cheaper than walking nanoflann's tree: the
// searches of k = 32 to 400 nearest take 1.4-1.7x less time (docs/performance.md, "The
// neighbours gathered by cells"). The squared distances are computed as nanoflann computes
// them (x, y, then z, each difference squared and added), so both find the same points with
// the same distances.
#ifndef LPD_ENERGY_CELL_GRID_H_
#define LPD_ENERGY_CELL_GRID_H_

#include <utility>
#include <vector>

#include "energy/point3.h"

namespace lpd::energy {

class CellGrid {
 public:
  // Cells of side `cell_size` (> 0) over the bounding box of `points`, made larger where the
  // box would need more than max(4 points, 4096) cells (a far point, a thin long cloud). The
  // grid keeps its own copy of the coordinates.
  CellGrid(const PointList& points, double cell_size);

  // Appends (index, squared distance) of every point at a squared distance under
  // `squared_radius` from `query` to `out`, in the grid's order (by cell, then by index).
  void Within(const Point3& query, double squared_radius,
              std::vector<std::pair<int, double>>* out) const;

  double cell_size() const { return cell_size_; }
  int size() const { return static_cast<int>(index_.size()); }  // the points

 private:
  // The cell of coordinate v along an axis of `cells` cells starting at `origin`, clamped to
  // the grid (a query beyond it scans the cells at its edge, which hold no point in reach).
  int CellAlong(double v, double origin, int cells) const;

  double cell_size_;
  Point3 origin_;
  int cells_x_ = 1, cells_y_ = 1, cells_z_ = 1;
  std::vector<int> first_slot_;  // cell c's points are slots [first_slot_[c], first_slot_[c+1])
  std::vector<int> index_;       // a slot's point
  std::vector<double> x_, y_, z_;  // a slot's coordinates
};

}  // namespace lpd::energy

#endif  // LPD_ENERGY_CELL_GRID_H_
