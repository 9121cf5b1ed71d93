#include "experiments/evaluation/mesh_distance.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include "energy/normalization.h"
#include "energy/point_kd_tree.h"

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

std::vector<double> MeshDistance::TriangleDistances(const energy::PointList& points,
                                                    int num_threads) const {
  if (points.empty()) throw std::invalid_argument("no points to measure the mesh against");
  const energy::PointListAdaptor adaptor{points};
  energy::L2PointKdTree tree(3, adaptor,
                             nanoflann::KDTreeSingleIndexAdaptorParams(energy::kKdTreeLeafSize));
  tree.buildIndex();
  const int m = num_triangles();
  std::vector<double> distances(m);
#pragma omp parallel num_threads(num_threads)
  {
    std::vector<std::pair<int, double>> found;
#pragma omp for schedule(dynamic, 256)
    for (int t = 0; t < m; ++t) {
      const Triangle& triangle = tree_->triangles[t];
      const energy::Point3 centroid(
          (triangle[0].x() + triangle[1].x() + triangle[2].x()) / 3.0,
          (triangle[0].y() + triangle[1].y() + triangle[2].y()) / 3.0,
          (triangle[0].z() + triangle[1].z() + triangle[2].z()) / 3.0);
      double reach = 0.0;  // the farthest the triangle gets from its centroid
      for (int v = 0; v < 3; ++v) {
        reach = std::max(reach, std::sqrt(CGAL::squared_distance(triangle[v], ToCgal(centroid))));
      }
      // The point nearest the centroid bounds the answer; any nearer point to the triangle
      // lies within that bound plus `reach` of the centroid.
      int nearest;
      double squared;
      nanoflann::KNNResultSet<double, int> result(1);
      result.init(&nearest, &squared);
      tree.findNeighbors(result, centroid.data(), nanoflann::SearchParams());
      double best = CGAL::squared_distance(ToCgal(points[nearest]), triangle);
      const double radius = std::sqrt(best) + reach;
      tree.radiusSearch(centroid.data(), radius * radius, found, nanoflann::SearchParams());
      for (const auto& [index, unused] : found) {
        best = std::min(best, CGAL::squared_distance(ToCgal(points[index]), triangle));
      }
      distances[t] = std::sqrt(best);
    }
  }
  return distances;
}

}  // namespace lpd::experiments
