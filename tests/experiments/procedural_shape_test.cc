// Procedural shapes: samples on the surface, exact distances against closed forms and brute
// force, area-uniform sampling (chi-square), feature distances, and spec parsing.
#include "experiments/shapes/procedural_shape.h"

#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include <gtest/gtest.h>

#include "experiments/shapes/shape_catalog.h"
#include "experiments/shapes/triangle_mesh.h"

namespace lpd::experiments {
namespace {

using energy::Point3;
using energy::PointList;

PointList RandomPoints(int count, double half_width, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coordinate(-half_width, half_width);
  PointList points;
  for (int i = 0; i < count; ++i) {
    points.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
  }
  return points;
}

TEST(ProceduralShape, EveryCatalogueShapeSamplesOnItsSurfaceWithUnitNormals) {
  for (const auto& [name, unused] : ShapeParameterDefaults()) {
    const ProceduralShape shape = MakeShape({name, {}});
    const SurfaceSamples samples = shape.Sample(2000, 3);
    ASSERT_EQ(samples.points.size(), 2000u);
    for (size_t i = 0; i < samples.points.size(); ++i) {
      ASSERT_LT(shape.DistanceToSurface(samples.points[i]), 1e-12) << name << " sample " << i;
      ASSERT_NEAR(samples.normals[i].norm(), 1.0, 1e-12) << name;
    }
  }
}

TEST(ProceduralShape, SameSeedSameSamplesOtherSeedOtherSamples) {
  const ProceduralShape shape = MakeShape({"cad_part", {}});
  EXPECT_EQ(shape.Sample(100, 9).points, shape.Sample(100, 9).points);
  EXPECT_NE(shape.Sample(100, 9).points, shape.Sample(100, 10).points);
}

// Closed forms for an axis-aligned box of half extents e centred at the origin.
double BoxDistance(const Point3& e, const Point3& p) {
  const Point3 q = p.cwiseAbs() - e;
  const double outside = q.cwiseMax(0.0).norm();
  return outside > 0.0 ? outside : -q.maxCoeff();
}

double BoxEdgeDistance(const Point3& e, const Point3& p) {
  const Point3 q = p.cwiseAbs();
  double best = INFINITY;
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    const double along = std::max(q[a] - e[a], 0.0);
    best = std::min(best, std::sqrt(along * along + std::pow(q[b] - e[b], 2) +
                                     std::pow(q[c] - e[c], 2)));
  }
  return best;
}

TEST(ProceduralShape, BoxDistancesMatchClosedForms) {
  const ProceduralShape box = MakeShape({"box", {{"size_x", 1.0}, {"size_y", 0.8}}});
  const Point3 e(0.5, 0.4, 0.3);
  for (const Point3& p : RandomPoints(3000, 1.0, 4)) {
    ASSERT_NEAR(box.DistanceToSurface(p), BoxDistance(e, p), 1e-12) << p.transpose();
    ASSERT_NEAR(box.DistanceToFeatures(p), BoxEdgeDistance(e, p), 1e-12) << p.transpose();
  }
  EXPECT_NEAR(box.Area(), 2 * (1.0 * 0.8 + 1.0 * 0.6 + 0.8 * 0.6), 1e-12);
}

TEST(ProceduralShape, ExactDistanceIsALowerBoundTightAgainstDenseSamples) {
  // Samples lie on the surface, so the nearest sample is never closer than the exact
  // distance, and with 300k samples it is at most a sample spacing farther.
  for (const char* name : {"sphere", "cylinder", "cone", "cad_part"}) {
    const ProceduralShape shape = MakeShape({name, {}});
    const PointList dense = shape.Sample(300000, 5).points;
    for (const Point3& p : RandomPoints(40, 0.9, 6)) {
      double brute = INFINITY;
      for (const Point3& s : dense) brute = std::min(brute, (s - p).norm());
      const double exact = shape.DistanceToSurface(p);
      ASSERT_LE(exact, brute + 1e-12) << name << " at " << p.transpose();
      ASSERT_LT(brute - exact, 0.01) << name << " at " << p.transpose();
    }
  }
}

TEST(ProceduralShape, AreasMatchClosedForms) {
  const double r = 0.5, h = 1.0;
  EXPECT_NEAR(MakeShape({"sphere", {}}).Area(), 4 * M_PI * r * r, 1e-12);
  EXPECT_NEAR(MakeShape({"cylinder", {}}).Area(), 2 * M_PI * r * h + 2 * M_PI * r * r, 1e-12);
  const double height = r / std::tan(M_PI / 6);  // apex angle 60 degrees
  EXPECT_NEAR(MakeShape({"cone", {}}).Area(), M_PI * r * (r + std::hypot(r, height)), 1e-12);
}

TEST(ProceduralShape, CubeSamplingIsUniformByChiSquare) {
  // 6 faces x 4 x 4 cells of equal area: 96 bins, 95 degrees of freedom; the 0.999 quantile
  // of chi-square(95) is about 143.
  const ProceduralShape cube = MakeShape({"cube", {}});
  const int count = 96000;
  std::vector<int> bins(96, 0);
  for (const Point3& p : cube.Sample(count, 11).points) {
    int axis = 0;
    p.cwiseAbs().maxCoeff(&axis);
    const int face = 2 * axis + (p[axis] > 0);
    const int u = std::min(3, static_cast<int>((p[(axis + 1) % 3] + 0.5) * 4));
    const int v = std::min(3, static_cast<int>((p[(axis + 2) % 3] + 0.5) * 4));
    ++bins[16 * face + 4 * u + v];
  }
  const double expected = count / 96.0;
  double chi_square = 0.0;
  for (int observed : bins) chi_square += std::pow(observed - expected, 2) / expected;
  EXPECT_LT(chi_square, 143.0);
}

TEST(ProceduralShape, ConeSamplingFollowsTheAreaElement) {
  // On a cone's side the area within radius r grows as r^2: a quarter lies within R/2.
  const ProceduralShape cone = MakeShape({"cone", {{"apex_angle", 90.0}}});
  int side = 0, inner = 0;
  for (const Point3& p : cone.Sample(200000, 12).points) {
    if (p.z() < 1e-12) continue;  // the base disk
    ++side;
    inner += std::hypot(p.x(), p.y()) < 0.25;
  }
  const double share = static_cast<double>(inner) / side;
  EXPECT_NEAR(share, 0.25, 0.005);
  // Side vs base: pi r l against pi r^2, l = r sqrt(2) for a right-angled apex.
  EXPECT_NEAR(static_cast<double>(side) / 200000, std::sqrt(2.0) / (1 + std::sqrt(2.0)), 0.005);
}

TEST(ProceduralShape, FeatureDistancesOfCylinderConeAndSphere) {
  const ProceduralShape cylinder = MakeShape({"cylinder", {}});
  // The rims are the circles of radius 0.5 at z = +-0.5.
  EXPECT_NEAR(cylinder.DistanceToFeatures(Point3(0, 0, 0.5)), 0.5, 1e-12);
  EXPECT_NEAR(cylinder.DistanceToFeatures(Point3(0.8, 0, 0.9)), 0.5, 1e-12);
  EXPECT_NEAR(cylinder.DistanceToFeatures(Point3(0, 0.5, 0)), 0.5, 1e-12);
  const ProceduralShape cone = MakeShape({"cone", {{"apex_angle", 90.0}}});
  EXPECT_NEAR(cone.DistanceToFeatures(Point3(0, 0, 0.6)), 0.1, 1e-12);  // apex at z = 0.5
  EXPECT_FALSE(MakeShape({"sphere", {}}).has_features());
  EXPECT_TRUE(std::isinf(MakeShape({"sphere", {}}).DistanceToFeatures(Point3::Zero())));
}

TEST(ProceduralShape, CadPartHasItsCutEdgesAndConcaveShoulder) {
  const ProceduralShape part = MakeShape({"cad_part", {}});
  // The two cuts (angles 0 and 270 degrees) meet along the z axis, which is an edge.
  EXPECT_NEAR(part.DistanceToFeatures(Point3(0, 0, 0.5)), 0.0, 1e-12);
  // The concave rim of the shoulder: radius 0.2 at z = 0.7, here at angle 90 degrees.
  EXPECT_NEAR(part.DistanceToFeatures(Point3(0, 0.2, 0.7)), 0.0, 1e-12);
  // The angle range excludes the fourth quadrant: a point there is off the surface.
  EXPECT_GT(part.DistanceToSurface(Point3(0.2, -0.2, 0.5)), 0.19);
  EXPECT_NEAR(part.DistanceToSurface(Point3(0.2, -0.3, 0.5)), 0.2, 1e-12);  // to the cut
}

TEST(ShapeCatalog, SpecsParseAndBadSpecsFailClearly) {
  const ShapeSpec spec = ParseShapeSpec("cone:apex_angle=30,radius=2");
  EXPECT_EQ(spec.name, "cone");
  EXPECT_EQ(spec.parameters.at("apex_angle"), 30.0);
  EXPECT_EQ(spec.parameters.at("radius"), 2.0);
  EXPECT_THROW(ParseShapeSpec("cone:apex_angle"), std::invalid_argument);
  EXPECT_THROW(ParseShapeSpec("cone:apex_angle=x"), std::invalid_argument);
  EXPECT_THROW(MakeShape({"teapot", {}}), std::invalid_argument);
  EXPECT_THROW(MakeShape({"cone", {{"height", 1.0}}}), std::invalid_argument);
  EXPECT_THROW(MakeShape({"cone", {{"apex_angle", 190.0}}}), std::invalid_argument);
  EXPECT_THROW(MakeShape({"sphere", {{"radius", -1.0}}}), std::invalid_argument);
}

TEST(TriangleMesh, SamplingIsProportionalToTriangleArea) {
  // Two triangles of areas 0.5 and 1.5.
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {3, 0, 0}, {4, 0, 0}, {3, 3, 0}};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
  const SurfaceSamples samples = SampleTriangleMesh(mesh, 100000, 13);
  int in_first = 0;
  for (const Point3& p : samples.points) {
    ASSERT_NEAR(p.z(), 0.0, 1e-15);
    in_first += p.x() < 2.0;
    if (p.x() < 2.0) {
      ASSERT_LE(p.x() + p.y(), 1.0 + 1e-12);
    }
  }
  EXPECT_NEAR(in_first / 100000.0, 0.25, 0.005);
  EXPECT_NEAR(samples.normals[0].z(), 1.0, 1e-12);
}

}  // namespace
}  // namespace lpd::experiments
