// lpd: exact point-to-surface distance to a triangle mesh (CGAL AABB tree).
//
// Kept in its own translation unit so that CGAL's headers are compiled once.
#ifndef LPD_EXPERIMENTS_EVALUATION_MESH_DISTANCE_H_
#define LPD_EXPERIMENTS_EVALUATION_MESH_DISTANCE_H_

#include <memory>
#include <string>
#include <vector>

#include "energy/normalization.h"
#include "experiments/shapes/triangle_mesh.h"

namespace lpd::experiments {

class MeshDistance {
 public:
  // Throws std::runtime_error if the mesh has no triangles.
  explicit MeshDistance(const TriangleMesh& mesh);
  ~MeshDistance();

  // Unsigned distance from each point to the nearest triangle, computed in parallel.
  std::vector<double> Distances(const energy::PointList& points, int num_threads) const;

  // Distance from each triangle (in mesh order) to the nearest of `points`, in parallel.
  // Throws std::invalid_argument if `points` is empty.
  std::vector<double> TriangleDistances(const energy::PointList& points, int num_threads) const;

  // Bounding-box diagonal of the mesh vertices.
  double BoundingBoxDiagonal() const { return diagonal_; }
  int num_triangles() const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
  double diagonal_ = 0.0;
};

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_EVALUATION_MESH_DISTANCE_H_
