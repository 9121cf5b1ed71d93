#include "energy/cell_grid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace lpd::energy {

CellGrid::CellGrid(const PointList& points, double cell_size) : cell_size_(cell_size) {
  if (!(cell_size > 0.0) || !std::isfinite(cell_size)) {
    throw std::invalid_argument("cell grid: the cell size must be positive and finite");
  }
  const size_t n = points.size();
  Point3 low = Point3::Zero(), high = Point3::Zero();
  if (n > 0) low = high = points[0];
  for (const Point3& p : points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  origin_ = low;
  const Point3 extent = high - low;
  const double max_cells = std::max(4.0 * static_cast<double>(n), 4096.0);
  auto count_along = [&](double length) { return std::floor(length / cell_size_) + 1.0; };
  // An extent past the doubles' range (points near +-1e308) leaves one cell: slow, still exact.
  const bool finite = std::isfinite(extent.x() + extent.y() + extent.z());
  while (finite) {
    const double cells = count_along(extent.x()) * count_along(extent.y()) *
                         count_along(extent.z());
    if (cells <= max_cells) break;
    cell_size_ *= std::max(1.01, std::cbrt(cells / max_cells));
  }
  if (finite) {
    cells_x_ = static_cast<int>(count_along(extent.x()));
    cells_y_ = static_cast<int>(count_along(extent.y()));
    cells_z_ = static_cast<int>(count_along(extent.z()));
  }
  const size_t num_cells = static_cast<size_t>(cells_x_) * cells_y_ * cells_z_;

  // A counting sort of the points by cell, stable: each cell's points in index order.
  std::vector<int> cell_of(n);
  first_slot_.assign(num_cells + 1, 0);
  for (size_t i = 0; i < n; ++i) {
    const Point3& p = points[i];
    cell_of[i] = (CellAlong(p.z(), origin_.z(), cells_z_) * cells_y_ +
                  CellAlong(p.y(), origin_.y(), cells_y_)) *
                     cells_x_ +
                 CellAlong(p.x(), origin_.x(), cells_x_);
    ++first_slot_[cell_of[i] + 1];
  }
  for (size_t c = 0; c < num_cells; ++c) first_slot_[c + 1] += first_slot_[c];
  std::vector<int> next_slot(first_slot_.begin(), first_slot_.end() - 1);
  index_.resize(n);
  x_.resize(n);
  y_.resize(n);
  z_.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const int slot = next_slot[cell_of[i]]++;
    index_[slot] = static_cast<int>(i);
    x_[slot] = points[i].x();
    y_[slot] = points[i].y();
    z_[slot] = points[i].z();
  }
}

int CellGrid::CellAlong(double v, double origin, int cells) const {
  // Clamped as a double first: a far query's cell may not fit in an int.
  const double cell = std::floor((v - origin) / cell_size_);
  return static_cast<int>(std::clamp(cell, 0.0, static_cast<double>(cells - 1)));
}

void CellGrid::Within(const Point3& query, double squared_radius,
                      std::vector<std::pair<int, double>>* out) const {
  if (index_.empty() || !(squared_radius > 0.0)) return;
  const double radius = std::sqrt(squared_radius);
  const int x0 = CellAlong(query.x() - radius, origin_.x(), cells_x_);
  const int x1 = CellAlong(query.x() + radius, origin_.x(), cells_x_);
  const int y0 = CellAlong(query.y() - radius, origin_.y(), cells_y_);
  const int y1 = CellAlong(query.y() + radius, origin_.y(), cells_y_);
  const int z0 = CellAlong(query.z() - radius, origin_.z(), cells_z_);
  const int z1 = CellAlong(query.z() + radius, origin_.z(), cells_z_);
  // The cells x0..x1 of a row are consecutive, and so are their slots [first, last): room
  // for all of the rows' slots is made at once, then the points within the radius are kept.
  const auto row_slots = [&](int z, int y) {
    const int row = (z * cells_y_ + y) * cells_x_;
    return std::make_pair(first_slot_[row + x0], first_slot_[row + x1 + 1]);
  };
  size_t count = out->size();
  size_t room = count;
  for (int z = z0; z <= z1; ++z) {
    for (int y = y0; y <= y1; ++y) {
      const auto [first, last] = row_slots(z, y);
      room += last - first;
    }
  }
  out->resize(room);
  std::pair<int, double>* appended = out->data();
  for (int z = z0; z <= z1; ++z) {
    for (int y = y0; y <= y1; ++y) {
      const auto [first, last] = row_slots(z, y);
      for (int slot = first; slot < last; ++slot) {
        // nanoflann's L2_Simple_Adaptor::evalMetric, term by term.
        double difference = query.x() - x_[slot];
        double squared = difference * difference;
        difference = query.y() - y_[slot];
        squared += difference * difference;
        difference = query.z() - z_[slot];
        squared += difference * difference;
        appended[count] = {index_[slot], squared};
        count += squared < squared_radius;  // written always, kept only within the radius
      }
    }
  }
  out->resize(count);
}

}  // namespace lpd::energy
