#include "experiments/shapes/triangle_mesh.h"

#include <limits>
#include <random>
#include <stdexcept>

#include "io/atomic_output_file.h"
#include "io/point_cloud_io.h"

namespace lpd::experiments {

using energy::Point3;

void CheckTriangleMeshPath(const std::string& path) {
  const std::string extension = io::FileExtension(path);
  if (extension != "off" && extension != "ply") {
    throw std::runtime_error("cannot write '" + path +
                             "': the mesh extension must be .off or .ply");
  }
}

void WriteTriangleMesh(const std::string& path, const TriangleMesh& mesh, bool overwrite) {
  CheckTriangleMeshPath(path);
  const std::string extension = io::FileExtension(path);
  io::AtomicOutputFile file(path, overwrite);
  std::ofstream& out = file.stream();
  out.precision(std::numeric_limits<double>::max_digits10);
  if (extension == "off") {
    out << "OFF\n" << mesh.vertices.size() << " " << mesh.triangles.size() << " 0\n";
  } else {
    out << "ply\nformat ascii 1.0\nelement vertex " << mesh.vertices.size()
        << "\nproperty double x\nproperty double y\nproperty double z\nelement face "
        << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  }
  for (const Point3& v : mesh.vertices) out << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const auto& t : mesh.triangles) out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  file.Commit();
}

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
