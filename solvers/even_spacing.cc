#include "solvers/even_spacing.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "energy/cell_grid.h"
#include "energy/knn_by_radius.h"
#include "energy/nearest_neighbors.h"
#include "solvers/lloyd_cell.h"
#include "solvers/median.h"

namespace lpd::solvers {
namespace {

constexpr int kNeighbors = 10;  // the neighbours whose bisectors bound a point's cell
static_assert(kNeighbors <= kMaxCellSites);
constexpr double kStep = 0.4;   // largest move per round, in units of h
// The cells of the later rounds' grids over the median distance to the kNeighbors-th
// neighbour: 0.7 took 20-25% off the stage on the sheets at 50K 1% against the tree, 0.5 10%.
constexpr double kCellOverFarthest = 0.7;
// The cell reaches beyond the neighbours' hull by half a row of a hexagonal lattice of the
// median nearest distance a: its rows lie sqrt(3) / 2 a apart.
constexpr double kHullMargin = 0.4330127018922193;  // sqrt(3) / 4
// A point with a neighbour whose normal is more than 30 degrees off its own sits at a sharp
// edge: its tangent plane would carry it off the other face, so it moves along the edge only.
// Where two such neighbours give edges more than 30 degrees apart (a corner), it stays.
constexpr double kMinNormalCosine = 0.866;

// The move of row r in a round: to the centroid of its cell (lloyd_cell.h) among the offsets
// of its neighbours `nearest` within its tangent plane, along the edge at a sharp edge, none at
// a corner; at most kStep h long.
energy::Point3 LloydMove(int r, const energy::PointList& current,
                         const energy::PointList& normals, const std::vector<int>& rows,
                         const int* nearest, const double* squared, int found, double margin,
                         double h) {
  const energy::Point3 stay = energy::Point3::Zero();
  const energy::Point3& p = current[r];
  const energy::Point3& n = normals[rows[r]];
  if (n.squaredNorm() == 0.0) return stay;
  const energy::Point3 u = n.unitOrthogonal(), v = n.cross(u);
  std::array<Eigen::Vector2d, kNeighbors + 1> sites;
  int num_sites = 0;
  energy::Point3 edge = energy::Point3::Zero();
  double edge_cosine = 1.0;  // 1: no sharp edge
  for (int a = 0; a < found; ++a) {
    if (nearest[a] == r || !(squared[a] > 0.0)) continue;
    const energy::Point3& m = normals[rows[nearest[a]]];
    const double cosine = std::abs(n.dot(m));
    if (cosine < kMinNormalCosine) {
      if (m.squaredNorm() == 0.0) return stay;
      const energy::Point3 along = n.cross(m).normalized();
      if (edge_cosine < 1.0 && std::abs(along.dot(edge)) < kMinNormalCosine) return stay;
      if (cosine < edge_cosine) {  // the edge of the most different face
        edge_cosine = cosine;
        edge = along;
      }
    }
    const energy::Point3 offset = current[nearest[a]] - p;
    const double height = n.dot(offset);
    // A neighbour more than 45 degrees off the tangent plane (across a thin part, or on a face
    // beyond a sharp edge) bounds no cell within it.
    if (2.0 * height * height > squared[a]) continue;
    sites[num_sites++] = {u.dot(offset), v.dot(offset)};
  }
  Eigen::Vector2d centroid;
  if (!ClippedCellCentroid(sites.data(), num_sites, margin, &centroid)) return stay;
  energy::Point3 move = centroid.x() * u + centroid.y() * v;
  if (edge_cosine < 1.0) move = edge * edge.dot(move);
  const double length = move.norm();
  return length > kStep * h ? energy::Point3(move * (kStep * h / length)) : move;
}

}  // namespace

energy::PointList SpreadEvenly(const energy::PointList& points, const energy::PointList& normals,
                               const std::vector<uint8_t>& movable, int rounds,
                               int num_threads, double* kernel) {
  std::vector<int> rows;  // the movable points
  for (size_t i = 0; i < points.size(); ++i) {
    if (movable[i]) rows.push_back(static_cast<int>(i));
  }
  energy::PointList result = points;
  const int count = static_cast<int>(rows.size());
  if (rounds <= 0 || count <= kNeighbors) return result;
  energy::PointList current(count);
  for (int r = 0; r < count; ++r) current[r] = points[rows[r]];
  double h = kernel && *kernel > 0.0 ? *kernel : 0.0;
  energy::PointList next(count);
  constexpr size_t kRow = kNeighbors + 1;  // a point's search results: itself and its nearest
  std::vector<int> neighbors(count * kRow);
  std::vector<double> squared(neighbors.size());
  std::vector<int> found(count);
  std::vector<double> nearest(count);
  std::vector<double> last_farthest(count);  // a point's last squared distance to its kRow-th
  for (int round = 0; round < rounds; ++round) {
    const auto take = [&](int r, const int* indices, const double* distances, int num_found) {
      std::copy(indices, indices + num_found, &neighbors[r * kRow]);
      std::copy(distances, distances + num_found, &squared[r * kRow]);
      found[r] = num_found;
      nearest[r] = num_found > 1 ? std::sqrt(distances[1]) : 0.0;
    };
    // The first round searches a tree. The points then move less than their spacing a round,
    // so a later round gathers each point's neighbours from a grid within a radius guessed
    // from its own last (knn_by_radius.h): a grid is cheaper to build than a tree, and the
    // guess rarely misses.
    double cell_size = 0.0;
    if (round > 0) {
      for (int r = 0; r < count; ++r) last_farthest[r] = squared[r * kRow + found[r] - 1];
      std::vector<double> farthest = last_farthest;
      cell_size = kCellOverFarthest * std::sqrt(Median(&farthest));
    }
    if (cell_size > 0.0 && std::isfinite(cell_size)) {
      const energy::CellGrid grid(current, cell_size);
#pragma omp parallel num_threads(num_threads)
      {
        energy::KnnByRadius by_radius;
        std::array<int, kRow> indices;
        std::array<double, kRow> distances;
#pragma omp for schedule(static)
        for (int r = 0; r < count; ++r) {
          by_radius.Guess(last_farthest[r]);
          take(r, indices.data(), distances.data(),
               by_radius.Search(nullptr, &grid, current[r], kRow, indices.data(),
                                distances.data()));
        }
      }
    } else {
      const energy::NearestNeighbors search(current);
      search.ForEach(count, kRow, num_threads, [&current](int r) { return current[r]; }, take);
    }
    const double median_nearest = Median(&nearest);
    if (!(h > 0.0)) {
      h = 2.0 * median_nearest;
      if (!(h > 0.0)) return result;
      if (kernel) *kernel = h;
    }
    const double margin = kHullMargin * median_nearest;
#pragma omp parallel for schedule(static) num_threads(num_threads)
    for (int r = 0; r < count; ++r) {
      next[r] = current[r] + LloydMove(r, current, normals, rows, &neighbors[r * kRow],
                                       &squared[r * kRow], found[r], margin, h);
    }
    current.swap(next);
  }
  for (int r = 0; r < count; ++r) result[rows[r]] = current[r];
  return result;
}

void HoldWithinInputs(const energy::PointList& start, const energy::PointList& inputs,
                      const energy::NeighborGraph& graph, const std::vector<uint8_t>& moved,
                      double margin, int num_threads, energy::PointList* spread) {
  const int n = static_cast<int>(start.size());
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int i = 0; i < n; ++i) {
    if (!moved[i]) continue;
    const energy::Point3 move = (*spread)[i] - start[i];
    const double length = move.norm();
    if (!(length > 0.0)) continue;
    const energy::Point3 direction = move / length;
    double reach = direction.dot(inputs[i] - start[i]);
    const int* neighbors = graph.NeighborsOf(i);
    for (int a = 0; a < graph.k; ++a) {
      reach = std::max(reach, direction.dot(inputs[neighbors[a]] - start[i]));
    }
    reach -= margin;
    if (length > reach) (*spread)[i] = start[i] + std::max(reach, 0.0) * direction;
  }
}

}  // namespace lpd::solvers
