#include "experiments/triangle_mesh.h"

#include <random>
#include <stdexcept>

namespace lpd::experiments {

using energy::Point3;

SurfaceSamples SampleTriangleMesh(const TriangleMesh& mesh, int count, uint64_t seed) {
  if (count < 0) throw std::invalid_argument("sample count must be >= 0");
  std::vector<double> areas;
  areas.reserve(mesh.triangles.size());
  double total = 0.0;
  for (const auto& t : mesh.triangles) {
    const Point3& a = mesh.vertices.at(t[0]);
    areas.push_back(0.5 * (mesh.vertices.at(t[1]) - a).cross(mesh.vertices.at(t[2]) - a).norm());
    total += areas.back();
  }
  if (!(total > 0.0)) throw std::invalid_argument("the mesh has zero area");
  std::discrete_distribution<size_t> pick(areas.begin(), areas.end());
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::mt19937_64 rng(seed);
  SurfaceSamples samples;
  samples.points.reserve(count);
  samples.normals.reserve(count);
  for (int n = 0; n < count; ++n) {
    const auto& t = mesh.triangles[pick(rng)];
    const Point3& a = mesh.vertices[t[0]];
    const Point3 ab = mesh.vertices[t[1]] - a;
    const Point3 ac = mesh.vertices[t[2]] - a;
    double u = unit(rng), v = unit(rng);
    if (u + v > 1.0) {  // fold the unit square onto the triangle, keeping uniformity
      u = 1.0 - u;
      v = 1.0 - v;
    }
    samples.points.push_back(a + u * ab + v * ac);
    samples.normals.push_back(ab.cross(ac).normalized());
  }
  return samples;
}

}  // namespace lpd::experiments
