// The neutral reconstructions: on clean samples of a sphere both make a closed surface
// through the samples whose area matches the sphere's, and meshes written as OFF or PLY read
// back identical.
#include "experiments/baselines/surface_reconstruction.h"

#include <cmath>
#include <filesystem>
#include <map>
#include <stdexcept>

#include <gtest/gtest.h>

#include "experiments/shapes/shape_catalog.h"

namespace lpd::experiments {
namespace {

constexpr double kPi = 3.14159265358979323846;

double Area(const TriangleMesh& mesh) {
  double area = 0.0;
  for (const auto& t : mesh.triangles) {
    const energy::Point3& a = mesh.vertices[t[0]];
    area += 0.5 * (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
  }
  return area;
}

// Every undirected edge of a closed surface is shared by exactly two triangles.
int BoundaryOrNonManifoldEdges(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : mesh.triangles) {
    for (int e = 0; e < 3; ++e) {
      const int a = t[e], b = t[(e + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  }
  int bad = 0;
  for (const auto& [edge, count] : uses) bad += count != 2;
  return bad;
}

TEST(SurfaceReconstruction, BothMethodsCloseASampledSphereWithItsArea) {
  const ProceduralShape sphere = MakeShape(ParseShapeSpec("sphere"));  // radius 0.5
  const energy::PointList points = sphere.Sample(3000, 2).points;
  const double true_area = 4.0 * kPi * 0.25;
  for (const Reconstruction method :
       {Reconstruction::kAdvancingFront, Reconstruction::kScaleSpace}) {
    ReconstructionOptions options;
    options.method = method;
    const TriangleMesh mesh = ReconstructSurface(points, options);
    ASSERT_EQ(mesh.vertices, points) << ToString(method) << ": vertices are the input points";
    // A closed triangulation of 3000 vertices of genus 0 has 2 * 3000 - 4 triangles.
    EXPECT_NEAR(static_cast<double>(mesh.triangles.size()), 2.0 * points.size() - 4, 30)
        << ToString(method);
    EXPECT_LE(BoundaryOrNonManifoldEdges(mesh), 30) << ToString(method);
    // Inscribed triangles: slightly less area than the sphere, never more.
    EXPECT_LT(Area(mesh), true_area) << ToString(method);
    EXPECT_GT(Area(mesh), 0.97 * true_area) << ToString(method);
  }
}

TEST(SurfaceReconstruction, WrittenMeshesReadBackIdentical) {
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1.0 / 3.0}};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const std::string directory = ::testing::TempDir();
  for (const std::string extension : {"off", "ply"}) {
    const std::string path = directory + "/tetrahedron." + extension;
    std::filesystem::remove(path);
    WriteTriangleMesh(path, mesh, /*overwrite=*/false);
    const TriangleMesh read = ReadTriangleMesh(path);
    EXPECT_EQ(read.vertices, mesh.vertices) << extension;
    EXPECT_EQ(read.triangles, mesh.triangles) << extension;
    // An existing file is refused without overwrite, and left as it was.
    EXPECT_THROW(WriteTriangleMesh(path, TriangleMesh(), /*overwrite=*/false),
                 std::runtime_error);
    EXPECT_EQ(ReadTriangleMesh(path).triangles.size(), 4u) << extension;
  }
  EXPECT_THROW(WriteTriangleMesh(directory + "/mesh.stl", mesh, true), std::runtime_error);
}

TEST(SurfaceReconstruction, RefusesTooFewCollinearOrCoincidentPointsAndUnknownNames) {
  EXPECT_THROW(ReconstructSurface({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, ReconstructionOptions()),
               std::invalid_argument);
  energy::PointList line, same(50, energy::Point3(1, 2, 3));
  for (int i = 0; i < 50; ++i) line.emplace_back(0.1 * i, 0.2 * i, -0.3 * i);
  for (const auto& points : {line, same}) {
    for (const Reconstruction method :
         {Reconstruction::kAdvancingFront, Reconstruction::kScaleSpace}) {
      ReconstructionOptions options;
      options.method = method;
      EXPECT_THROW(ReconstructSurface(points, options), std::invalid_argument);
    }
  }
  EXPECT_THROW(ParseReconstruction("poisson"), std::invalid_argument);
}

}  // namespace
}  // namespace lpd::experiments
