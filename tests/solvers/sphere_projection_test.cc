// The sphere projection against closed forms: on a sphere with exact tangent planes it puts
// every point back on the sphere; with noisy plane offsets it averages them over the
// neighbours without the curvature bias of a wider plane; a neighbour across a cut pair
// (m_ij = 0) does not enter the fit.
#include "solvers/sphere_projection.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "energy/variables.h"
#include "solvers/final_denoising.h"

namespace lpd::solvers {
namespace {

constexpr double kRadius = 0.3;

// Points on a sphere of radius kRadius about the origin, each moved along its normal by a
// Gaussian of deviation `radial`; t_i is the tangent plane at the point it came from, moved
// along the normal by a Gaussian of deviation `plane_offset`. Identity frame.
struct DisplacedSphere {
  energy::Problem problem;
  energy::Variables variables;
};

DisplacedSphere MakeDisplacedSphere(int n, double radial, double plane_offset) {
  std::mt19937_64 random(5);
  std::normal_distribution<double> gaussian;
  DisplacedSphere sphere;
  energy::PlaneField t(n, 4);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d normal =
        Eigen::Vector3d(gaussian(random), gaussian(random), gaussian(random)).normalized();
    const Eigen::Vector3d on_sphere = kRadius * normal;
    sphere.problem.points.push_back(on_sphere + radial * gaussian(random) * normal);
    t.row(i) << normal.transpose(), -normal.dot(on_sphere) - plane_offset * gaussian(random);
  }
  sphere.problem.graph = energy::BuildNeighborGraph(sphere.problem.points, 10, 1);
  energy::ComputeWeights(1e-4, &sphere.problem);
  sphere.variables = energy::InitialVariables(sphere.problem);
  sphere.variables.t = t;
  return sphere;
}

double LargestDistanceToTheSphere(const energy::PointList& points) {
  double largest = 0.0;
  for (const energy::Point3& p : points) largest = std::max(largest, std::abs(p.norm() - kRadius));
  return largest;
}

double RmsDistanceToTheSphere(const energy::PointList& points) {
  double sum = 0.0;
  for (const energy::Point3& p : points) sum += std::pow(p.norm() - kRadius, 2);
  return std::sqrt(sum / points.size());
}

TEST(SphereProjection, ExactTangentPlanesPutEveryPointBackOnTheSphere) {
  const DisplacedSphere sphere = MakeDisplacedSphere(2000, 0.01, 0.0);
  energy::PointList projected, normals;
  ProjectOntoOwnSurfaces(sphere.problem,
                         FitLocalSpheres(sphere.problem, sphere.variables, 2), &projected, &normals);
  EXPECT_LT(LargestDistanceToTheSphere(projected), 1e-9);
  for (size_t i = 0; i < projected.size(); ++i) {
    ASSERT_NEAR(normals[i].dot(projected[i].normalized()), 1.0, 1e-9) << "normal " << i;
  }
}

TEST(SphereProjection, AveragesNoisyPlaneOffsetsOverTheNeighbours) {
  constexpr double kOffsetNoise = 0.002;
  const DisplacedSphere sphere = MakeDisplacedSphere(4000, 0.01, kOffsetNoise);
  energy::PointList on_spheres, on_planes, normals;
  ProjectOntoOwnSurfaces(sphere.problem,
                         FitLocalSpheres(sphere.problem, sphere.variables, 2), &on_spheres, &normals);
  ProjectOntoOwnSurfaces(sphere.problem, TangentPlaneSurfaces(sphere.variables), &on_planes,
                         &normals);
  // Each plane's own offset error stays in its projection; the sphere fit averages about
  // 15 partners' (measured: RMS about a third of the plane projection's).
  EXPECT_NEAR(RmsDistanceToTheSphere(on_planes), kOffsetNoise, 0.1 * kOffsetNoise);
  EXPECT_LT(RmsDistanceToTheSphere(on_spheres), 0.5 * RmsDistanceToTheSphere(on_planes));
}

TEST(SphereProjection, CutPairsStayOutOfTheFit) {
  DisplacedSphere sphere = MakeDisplacedSphere(1000, 0.01, 0.0);
  // Tilt one neighbour's plane of point 0 far off and cut its pair: the fit must not see it.
  const auto& graph = sphere.problem.graph;
  const int pair = graph.incident_pairs[graph.incident_offsets[0]];
  const int j = graph.pairs[pair][0] == 0 ? graph.pairs[pair][1] : graph.pairs[pair][0];
  sphere.variables.t.row(j) << 1, 0, 0, 0.5;
  sphere.variables.m[pair] = 0.0;
  energy::PointList projected, normals;
  ProjectOntoOwnSurfaces(sphere.problem,
                         FitLocalSpheres(sphere.problem, sphere.variables, 1), &projected, &normals);
  EXPECT_LT(std::abs(projected[0].norm() - kRadius), 1e-9);
  sphere.variables.m[pair] = 1.0;  // with the pair kept, the tilted plane pulls the fit off
  ProjectOntoOwnSurfaces(sphere.problem,
                         FitLocalSpheres(sphere.problem, sphere.variables, 1), &projected, &normals);
  EXPECT_GT(std::abs(projected[0].norm() - kRadius), 1e-6);
}

}  // namespace
}  // namespace lpd::solvers
