// The learned denoisers' benchmark figures against brute force with an independent
// point-triangle distance, and Poisson-disk sampling against its defining properties.
#include "experiments/evaluation/benchmark_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "experiments/evaluation/ground_truth.h"
#include "experiments/shapes/poisson_disk_sampling.h"
#include "experiments/shapes/shape_catalog.h"

namespace lpd::experiments {
namespace {

using energy::Point3;
using energy::PointList;

PointList RandomPoints(int count, double spread, std::mt19937_64* random) {
  std::normal_distribution<double> normal(0.0, spread);
  PointList points(count);
  for (Point3& p : points) p = Point3(normal(*random), normal(*random), normal(*random));
  return points;
}

double SegmentDistance(const Point3& p, const Point3& a, const Point3& b) {
  const Point3 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

// Exact, without CGAL: the foot of the perpendicular if it falls inside the triangle (all
// three edge functions agree in sign), the nearest edge point otherwise.
double TriangleDistance(const Point3& p, const Point3& a, const Point3& b, const Point3& c) {
  const Point3 normal = (b - a).cross(c - a).normalized();
  const Point3 foot = p - normal.dot(p - a) * normal;
  const double u = normal.dot((b - a).cross(foot - a));
  const double v = normal.dot((c - b).cross(foot - b));
  const double w = normal.dot((a - c).cross(foot - c));
  if (u >= 0 && v >= 0 && w >= 0) return std::abs(normal.dot(p - a));
  return std::min({SegmentDistance(p, a, b), SegmentDistance(p, b, c), SegmentDistance(p, c, a)});
}

double BruteRadius(const PointList& points) {
  Point3 low = points[0], high = points[0];
  for (const Point3& p : points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  double radius = 0.0;
  for (const Point3& p : points) radius = std::max(radius, (p - 0.5 * (low + high)).norm());
  return radius;
}

TEST(BenchmarkMetrics, ChamferDistanceMatchesBruteForce) {
  std::mt19937_64 random(7);
  PointList clean = RandomPoints(700, 3.0, &random);
  for (Point3& p : clean) p += Point3(10, -4, 2);  // off the origin: the centre must not matter
  PointList result = RandomPoints(500, 3.0, &random);
  for (Point3& p : result) p += Point3(10.5, -4, 2);
  auto one_way = [](const PointList& from, const PointList& to) {
    double sum = 0.0;
    for (const Point3& x : from) {
      double best = std::numeric_limits<double>::infinity();
      for (const Point3& y : to) best = std::min(best, (x - y).squaredNorm());
      sum += best;
    }
    return sum / from.size();
  };
  const double radius = BruteRadius(clean);
  const double expected =
      1e4 * (one_way(result, clean) + one_way(clean, result)) / (radius * radius);
  EXPECT_NEAR(ChamferDistanceX1e4(result, clean, 2), expected, 1e-9 * expected);
}

TEST(BenchmarkMetrics, ChamferDistanceIsScaleFreeAndZeroOnItself) {
  std::mt19937_64 random(3);
  const PointList clean = RandomPoints(300, 1.0, &random);
  EXPECT_EQ(ChamferDistanceX1e4(clean, clean, 1), 0.0);
  const PointList result = RandomPoints(300, 1.0, &random);
  PointList clean_scaled = clean, result_scaled = result;
  for (Point3& p : clean_scaled) p *= 37.0;
  for (Point3& p : result_scaled) p *= 37.0;
  const double cd = ChamferDistanceX1e4(result, clean, 1);
  EXPECT_NEAR(ChamferDistanceX1e4(result_scaled, clean_scaled, 1), cd, 1e-9 * cd);
}

TEST(BenchmarkMetrics, PointToMeshDistanceMatchesBruteForce) {
  // An irregular closed mesh: a randomly perturbed octahedron, plus a sliver triangle.
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  TriangleMesh mesh;
  for (const Point3& v : {Point3(2, 0, 0), Point3(-2, 0, 0), Point3(0, 2, 0), Point3(0, -2, 0),
                          Point3(0, 0, 2), Point3(0, 0, -2)}) {
    mesh.vertices.push_back(v + Point3(jitter(random), jitter(random), jitter(random)));
  }
  mesh.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                    {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  mesh.vertices.push_back(Point3(3, 3, 3));
  mesh.vertices.push_back(Point3(3.01, 3, 3.5));
  mesh.triangles.push_back({4, 6, 7});
  const GroundTruth truth = MeshGroundTruth(mesh, "octahedron", 1000, 1);
  const PointList result = RandomPoints(400, 1.5, &random);

  double to_mesh = 0.0;
  for (const Point3& p : result) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& t : mesh.triangles) {
      best = std::min(best, TriangleDistance(p, mesh.vertices[t[0]], mesh.vertices[t[1]],
                                             mesh.vertices[t[2]]));
    }
    to_mesh += best * best;
  }
  double to_points = 0.0;
  for (const auto& t : mesh.triangles) {
    double best = std::numeric_limits<double>::infinity();
    for (const Point3& p : result) {
      best = std::min(best, TriangleDistance(p, mesh.vertices[t[0]], mesh.vertices[t[1]],
                                             mesh.vertices[t[2]]));
    }
    to_points += best * best;
  }
  const double radius = BruteRadius(mesh.vertices);
  const double expected =
      1e4 * (to_mesh / result.size() + to_points / mesh.triangles.size()) / (radius * radius);
  EXPECT_NEAR(PointToMeshDistanceX1e4(result, truth, 2), expected, 1e-9 * expected);
}

TEST(BenchmarkMetrics, PointToMeshDistanceOfAPlaneOffsetByAKnownDistance) {
  // Points filling a unit square at height h above a two-triangle square: the first half is
  // h^2; every triangle has a point at distance h, so the second half is h^2 too.
  TriangleMesh square;
  square.vertices = {Point3(0, 0, 0), Point3(1, 0, 0), Point3(1, 1, 0), Point3(0, 1, 0)};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  const double h = 0.01;
  PointList points;
  for (int x = 0; x <= 20; ++x) {
    for (int y = 0; y <= 20; ++y) points.emplace_back(x / 20.0, y / 20.0, h);
  }
  const GroundTruth truth = MeshGroundTruth(square, "square", 100, 1);
  const double radius = std::sqrt(0.5);
  EXPECT_NEAR(PointToMeshDistanceX1e4(points, truth, 1), 1e4 * 2 * h * h / (radius * radius),
              1e-12);
  EXPECT_TRUE(std::isnan(PointToMeshDistanceX1e4(points, PointSetGroundTruth(points, "p"), 1)));
}

double MinimumSpacing(const PointList& points) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < points.size(); ++i) {
    for (size_t j = i + 1; j < points.size(); ++j) {
      best = std::min(best, (points[i] - points[j]).norm());
    }
  }
  return best;
}

TEST(PoissonDiskSampling, KeepsTheCountFromTheCandidatesAndSpreadsThemOut) {
  const ProceduralShape sheets = MakeShape(ParseShapeSpec("sheets:size=1,gap=0.5"));
  const int count = 2000;
  const SurfaceSamples samples = PoissonDiskSample(sheets, count, 5);
  ASSERT_EQ(samples.points.size(), static_cast<size_t>(count));
  ASSERT_EQ(samples.normals.size(), static_cast<size_t>(count));
  for (const Point3& p : samples.points) EXPECT_LT(sheets.DistanceToSurface(p), 1e-12);
  // r_max: the disk radius of `count` disks packed hexagonally over the area (2 m^2).
  const double r_max = std::sqrt(2.0 / (2.0 * std::sqrt(3.0) * count));
  const double poisson = MinimumSpacing(samples.points);
  const double uniform = MinimumSpacing(sheets.Sample(count, 5).points);
  EXPECT_GT(poisson, 0.5 * r_max);
  EXPECT_LT(uniform, 0.1 * r_max);
  // Deterministic.
  EXPECT_EQ(PoissonDiskSample(sheets, count, 5).points, samples.points);
}

TEST(PoissonDiskSampling, RefusesImpossibleCounts) {
  SurfaceSamples dense;
  dense.points = {Point3(0, 0, 0), Point3(1, 0, 0)};
  dense.normals = dense.points;
  EXPECT_THROW(EliminateSamples(dense, 3, 1.0), std::invalid_argument);
  EXPECT_THROW(EliminateSamples(dense, 0, 1.0), std::invalid_argument);
  EXPECT_THROW(EliminateSamples(dense, 1, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace lpd::experiments
