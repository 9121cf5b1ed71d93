#include "experiments/mesh_distance.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

namespace lpd::experiments {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using CgalPoint = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using TriangleIterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

}  // namespace

struct MeshDistance::Tree {
  std::vector<Triangle> triangles;
  AabbTree tree;
};

MeshDistance::MeshDistance(const std::string& mesh_path) : tree_(std::make_unique<Tree>()) {
  // Checked here so the error names the file (CGAL's reader prints its own unnamed message).
  if (!std::ifstream(mesh_path)) {
    throw std::runtime_error(mesh_path + ": cannot open mesh file (missing or unreadable)");
  }
  std::vector<CgalPoint> vertices;
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_polygon_soup(mesh_path, vertices, polygons) || vertices.empty()) {
    throw std::runtime_error(mesh_path + ": cannot read a triangle mesh");
  }
  energy::PointList corners;
  corners.reserve(vertices.size());
  for (const CgalPoint& v : vertices) corners.emplace_back(v.x(), v.y(), v.z());
  diagonal_ = energy::BoundingBoxDiagonal(corners);
  for (const auto& polygon : polygons) {
    for (size_t c = 1; c + 1 < polygon.size(); ++c) {
      tree_->triangles.emplace_back(vertices.at(polygon[0]), vertices.at(polygon[c]),
                                    vertices.at(polygon[c + 1]));
    }
  }
  if (tree_->triangles.empty()) throw std::runtime_error(mesh_path + ": the mesh has no faces");
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
    const CgalPoint query(points[i].x(), points[i].y(), points[i].z());
    distances[i] = std::sqrt(tree_->tree.squared_distance(query));
  }
  return distances;
}

}  // namespace lpd::experiments
