#include "experiments/evaluation/mesh_distance.h"

#include <cmath>
#include <stdexcept>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include "energy/normalization.h"

namespace lpd::experiments {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using CgalPoint = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using TriangleIterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

CgalPoint ToCgal(const energy::Point3& p) { return CgalPoint(p.x(), p.y(), p.z()); }

}  // namespace

struct MeshDistance::Tree {
  std::vector<Triangle> triangles;
  AabbTree tree;
};

MeshDistance::MeshDistance(const TriangleMesh& mesh) : tree_(std::make_unique<Tree>()) {
  diagonal_ = energy::BoundingBoxDiagonal(mesh.vertices);
  for (const auto& t : mesh.triangles) {
    tree_->triangles.emplace_back(ToCgal(mesh.vertices.at(t[0])), ToCgal(mesh.vertices.at(t[1])),
                                  ToCgal(mesh.vertices.at(t[2])));
  }
  if (tree_->triangles.empty()) throw std::runtime_error("the mesh has no faces");
  tree_->tree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
  tree_->tree.build();
  tree_->tree.accelerate_distance_queries();
}

MeshDistance::~MeshDistance() = default;

int MeshDistance::num_triangles() const { return static_cast<int>(tree_->triangles.size()); }

std::vector<double> MeshDistance::Distances(const energy::PointList& points,
                                            int num_threads) const {
  std::vector<double> distances(points.size());
  const int n = static_cast<int>(points.size());
#pragma omp parallel for schedule(dynamic, 256) num_threads(num_threads)
  for (int i = 0; i < n; ++i) {
    distances[i] = std::sqrt(tree_->tree.squared_distance(ToCgal(points[i])));
  }
  return distances;
}

}  // namespace lpd::experiments
