#include "solvers/lloyd_cell.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace lpd::solvers {
namespace {

// A convex polygon, counter-clockwise, in one of two buffers that the clips alternate between.
// Each clip by a half-plane adds at most one vertex: a square clipped by the hull's edges (at
// most kMaxCellSites + 1) and the bisectors stays within kCapacity.
constexpr int kCapacity = 4 + 2 * kMaxCellSites + 1;
struct Polygon {
  std::array<Eigen::Vector2d, kCapacity> buffers[2];
  int current = 0;
  int size = 0;
  const Eigen::Vector2d& operator[](int v) const { return buffers[current][v]; }
};

// Keeps the part of `polygon` where normal . x <= limit (Sutherland-Hodgman, one plane).
void Clip(const Eigen::Vector2d& normal, double limit, Polygon* polygon) {
  const auto& from = polygon->buffers[polygon->current];
  auto& to = polygon->buffers[1 - polygon->current];
  int kept = 0;
  for (int v = 0; v < polygon->size; ++v) {
    const Eigen::Vector2d& p = from[v];
    const Eigen::Vector2d& q = from[(v + 1) % polygon->size];
    const double fp = normal.dot(p) - limit, fq = normal.dot(q) - limit;
    if (fp <= 0.0) to[kept++] = p;
    if ((fp < 0.0 && fq > 0.0) || (fp > 0.0 && fq < 0.0)) to[kept++] = p + fp / (fp - fq) * (q - p);
  }
  polygon->current = 1 - polygon->current;
  polygon->size = kept;
}

double Cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

}  // namespace

bool ClippedCellCentroid(const Eigen::Vector2d* sites, int count, double margin,
                         Eigen::Vector2d* centroid) {
  // The hull of the origin and the sites (Andrew's monotone chain), counter-clockwise.
  std::array<Eigen::Vector2d, kMaxCellSites + 1> points;
  int num_points = 0;
  points[num_points++] = Eigen::Vector2d::Zero();
  double reach = 0.0;
  for (int a = 0; a < count; ++a) {
    if (sites[a].squaredNorm() == 0.0) continue;
    points[num_points++] = sites[a];
    reach = std::max(reach, sites[a].norm());
  }
  if (num_points == 1) return false;
  std::sort(points.begin(), points.begin() + num_points,
            [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
              return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
            });
  std::array<Eigen::Vector2d, 2 * (kMaxCellSites + 1)> hull;
  int k = 0;
  for (int i = 0; i < num_points; ++i) {
    while (k >= 2 && Cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (int i = num_points - 2, lower = k + 1; i >= 0; --i) {
    while (k >= lower && Cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  // A square that holds the grown hull, then each grown hull edge and each bisector.
  Polygon cell;
  const double half = reach + margin;
  cell.buffers[0][0] = {-half, -half};
  cell.buffers[0][1] = {half, -half};
  cell.buffers[0][2] = {half, half};
  cell.buffers[0][3] = {-half, half};
  cell.size = 4;
  for (int e = 0; e + 1 < k && cell.size > 0; ++e) {
    const Eigen::Vector2d edge = hull[e + 1] - hull[e];
    const double length = edge.norm();
    if (!(length > 0.0)) continue;
    const Eigen::Vector2d outward(edge.y() / length, -edge.x() / length);
    Clip(outward, outward.dot(hull[e]) + margin, &cell);
  }
  for (int a = 0; a < count && cell.size > 0; ++a) {
    if (sites[a].squaredNorm() == 0.0) continue;
    Clip(sites[a], 0.5 * sites[a].squaredNorm(), &cell);  // |x| <= |x - s_a|
  }
  // The centroid of the polygon (shoelace).
  double area = 0.0;
  Eigen::Vector2d moment = Eigen::Vector2d::Zero();
  for (int v = 0; v < cell.size; ++v) {
    const Eigen::Vector2d& p = cell[v];
    const Eigen::Vector2d& q = cell[(v + 1) % cell.size];
    const double cross = p.x() * q.y() - q.x() * p.y();
    area += cross;
    moment += (p + q) * cross;
  }
  if (!(area > 0.0)) return false;
  *centroid = moment / (3.0 * area);
  return true;
}

}  // namespace lpd::solvers
