#include "solvers/even_spacing.h"

#include <algorithm>
#include <cmath>

#include "energy/nearest_neighbors.h"
#include "solvers/median.h"

namespace lpd::solvers {
namespace {

constexpr int kNeighbors = 10;  // pushing neighbours of a point
constexpr double kStep = 0.4;   // largest move per round, in units of h
// A point with a neighbour whose normal is more than 30 degrees off its own sits at a sharp
// edge: its tangent plane would carry it off the other face, so it moves along the edge only.
// Where two such neighbours give edges more than 30 degrees apart (a corner), it stays.
constexpr double kMinNormalCosine = 0.866;

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
  for (int round = 0; round < rounds; ++round) {
    const energy::NearestNeighbors search(current);
    auto query = [&current](int r) { return current[r]; };
    if (!(h > 0.0)) {
      std::vector<double> nearest(count, 0.0);
      search.ForEach(count, 2, num_threads, query,
                     [&](int r, const int*, const double* squared, int found) {
                       nearest[r] = found > 1 ? std::sqrt(squared[1]) : 0.0;
                     });
      h = 2.0 * Median(&nearest);
      if (!(h > 0.0)) return result;
      if (kernel) *kernel = h;
    }
    search.ForEach(count, kNeighbors + 1, num_threads, query,
                   [&](int r, const int* nearest, const double* squared, int found) {
                     const energy::Point3& p = current[r];
                     const energy::Point3& n = normals[rows[r]];
                     next[r] = p;
                     if (n.squaredNorm() == 0.0) return;
                     energy::Point3 force = energy::Point3::Zero();
                     energy::Point3 edge = energy::Point3::Zero();  // zero: no sharp edge
                     double edge_cosine = 1.0;
                     for (int a = 0; a < found; ++a) {
                       if (nearest[a] == r || !(squared[a] > 0.0)) continue;
                       const energy::Point3& m = normals[rows[nearest[a]]];
                       const double cosine = std::abs(n.dot(m));
                       if (cosine < kMinNormalCosine) {
                         if (m.squaredNorm() == 0.0) return;
                         const energy::Point3 along = n.cross(m).normalized();
                         if (edge_cosine < 1.0 && std::abs(along.dot(edge)) < kMinNormalCosine) {
                           return;  // at a corner: stays
                         }
                         if (cosine < edge_cosine) {  // the edge of the most different face
                           edge_cosine = cosine;
                           edge = along;
                         }
                       }
                       const double distance = std::sqrt(squared[a]);
                       force += (p - current[nearest[a]]) / distance *
                                std::exp(-4.0 * squared[a] / (h * h));
                     }
                     force -= n * n.dot(force);
                     if (edge_cosine < 1.0) force = edge * edge.dot(force);
                     next[r] = p + kStep * h * force / std::max(1.0, force.norm());
                   });
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
