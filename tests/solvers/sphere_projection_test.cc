// The sphere projection against closed forms: on a sphere with exact tangent planes it puts
// every point back on the sphere; with noisy plane offsets it averages them over the
// neighbours without the curvature bias of a wider plane; a neighbour across a cut pair
// (m_ij = 0) does not enter the fit.
#include "solvers/sphere_projection.h"

#include <cmath>

#include <gtest/gtest.h>

#include "energy/variables.h"
#include "solvers/final_denoising.h"
#include "tests/solvers/displaced_sphere.h"

namespace lpd::solvers {
namespace {

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
