// ReadTriangleMesh (declared in triangle_mesh.h), with CGAL's polygon-soup reader.
#include <fstream>
#include <stdexcept>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

#include "experiments/shapes/triangle_mesh.h"

namespace lpd::experiments {

TriangleMesh ReadTriangleMesh(const std::string& path) {
  // Checked here so the error names the file (CGAL's reader prints its own unnamed message).
  if (!std::ifstream(path)) {
    throw std::runtime_error(path + ": cannot open mesh file (missing or unreadable)");
  }
  using CgalPoint = CGAL::Simple_cartesian<double>::Point_3;
  std::vector<CgalPoint> vertices;
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_polygon_soup(path, vertices, polygons) || vertices.empty()) {
    throw std::runtime_error(path + ": cannot read a triangle mesh");
  }
  TriangleMesh mesh;
  mesh.vertices.reserve(vertices.size());
  for (const CgalPoint& v : vertices) {
    mesh.vertices.emplace_back(v.x(), v.y(), v.z());
    if (!mesh.vertices.back().allFinite()) {
      throw std::runtime_error(path + ": a vertex has a non-finite coordinate");
    }
  }
  for (const auto& polygon : polygons) {
    for (std::size_t index : polygon) {
      if (index >= vertices.size()) {
        throw std::runtime_error(path + ": a face refers to a missing vertex");
      }
    }
    for (size_t c = 1; c + 1 < polygon.size(); ++c) {
      mesh.triangles.push_back({static_cast<int>(polygon[0]), static_cast<int>(polygon[c]),
                                static_cast<int>(polygon[c + 1])});
    }
  }
  if (mesh.triangles.empty()) throw std::runtime_error(path + ": the mesh has no faces");
  return mesh;
}

}  // namespace lpd::experiments
