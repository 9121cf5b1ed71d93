// The sphere projection against closed forms: on a sphere with exact tangent planes it puts
// every point back on the sphere; with noisy plane offsets it averages them over the
// neighbours without the curvature bias of a wider plane; a neighbour across a cut pair
// (m_ij = 0) does not enter the fit; a blend of surfaces is their mean and averages their
// noise further.
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
  ProjectOntoBlendedSurfaces(sphere.problem, FitLocalSpheres(sphere.problem, sphere.variables, 2),
                             1, 0.0, false, 2, &projected, &normals);
  EXPECT_LT(LargestDistanceToTheSphere(projected), 1e-9);
  for (size_t i = 0; i < projected.size(); ++i) {
    ASSERT_NEAR(normals[i].dot(projected[i].normalized()), 1.0, 1e-9) << "normal " << i;
  }
}

TEST(SphereProjection, AveragesNoisyPlaneOffsetsOverTheNeighbours) {
  constexpr double kOffsetNoise = 0.002;
  const DisplacedSphere sphere = MakeDisplacedSphere(4000, 0.01, kOffsetNoise);
  energy::PointList on_spheres, on_planes, normals;
  ProjectOntoBlendedSurfaces(sphere.problem, FitLocalSpheres(sphere.problem, sphere.variables, 2),
                             1, 0.0, false, 2, &on_spheres, &normals);
  ProjectOntoBlendedSurfaces(sphere.problem, TangentPlaneSurfaces(sphere.variables), 1, 0.0,
                             false, 2, &on_planes, &normals);
  // Each plane's own offset error stays in its projection; the sphere fit averages about
  // 15 partners' (measured: RMS about a third of the plane projection's).
  EXPECT_NEAR(RmsDistanceToTheSphere(on_planes), kOffsetNoise, 0.1 * kOffsetNoise);
  EXPECT_LT(RmsDistanceToTheSphere(on_spheres), 0.5 * RmsDistanceToTheSphere(on_planes));
}

// Planes z = c_j, written as u0 + u.x = 0 with |u| = 2 and alternating signs.
std::vector<LocalSurface> HorizontalPlanes(const std::vector<double>& heights) {
  std::vector<LocalSurface> surfaces(heights.size());
  for (size_t j = 0; j < heights.size(); ++j) {
    surfaces[j].kind = LocalSurface::Kind::kPlane;
    surfaces[j].plane << 0, 0, (j % 2 ? -2 : 2), (j % 2 ? 2 : -2) * heights[j];
    surfaces[j].orientation << 0, 0, 1;
  }
  return surfaces;
}

TEST(SphereProjection, TheBlendOfTwoParallelPlanesFollowsTheWeightRule) {
  // p between z = 0.1 (the first candidate) and z = 0.4. At scale 0.36 the second plane, 0.3
  // from the first one's projection, weighs (1 + 0.09 / 0.36)^-2 = 0.64: the mean is
  // z1 = (0.1 + 0.64 * 0.4) / 1.64. Reweighted about z1, each plane weighs
  // (1 + (z - z1)^2 / 0.36)^-2, and p lands at their weighted mean, keeping x and y. At scale 0
  // the blend is the plain mean.
  const std::vector<LocalSurface> surfaces = HorizontalPlanes({0.1, 0.4});
  const int candidates[] = {0, 1};
  Eigen::Vector3d projected, normal;
  ASSERT_TRUE(ProjectOntoBlend(surfaces, candidates, 2, Eigen::Vector3d(0.5, -0.2, 0.0), 0.36,
                               &projected, &normal));
  const double z1 = 0.356 / 1.64;
  const double w_low = std::pow(1.0 + (z1 - 0.1) * (z1 - 0.1) / 0.36, -2.0);
  const double w_high = std::pow(1.0 + (0.4 - z1) * (0.4 - z1) / 0.36, -2.0);
  const double z2 = (0.1 * w_low + 0.4 * w_high) / (w_low + w_high);
  EXPECT_GT(z2, z1);  // the second step leans less toward the first surface
  EXPECT_NEAR((projected - Eigen::Vector3d(0.5, -0.2, z2)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((normal - Eigen::Vector3d(0, 0, 1)).norm(), 0.0, 1e-15);
  ASSERT_TRUE(ProjectOntoBlend(surfaces, candidates, 2, Eigen::Vector3d(0.5, -0.2, 0.0), 0.0,
                               &projected, &normal));
  EXPECT_NEAR(projected.z(), 0.25, 1e-15);
  // Planes that agree (at one height) blend into that plane; none with a surface: false.
  const std::vector<LocalSurface> same = HorizontalPlanes({0.25, 0.25, 0.25});
  const int three[] = {2, 0, 1};
  ASSERT_TRUE(ProjectOntoBlend(same, three, 3, Eigen::Vector3d(0.7, -1.2, 3.0), 0.01,
                               &projected, &normal));
  EXPECT_NEAR((projected - Eigen::Vector3d(0.7, -1.2, 0.25)).norm(), 0.0, 1e-15);
  std::vector<LocalSurface> none(2);
  EXPECT_FALSE(ProjectOntoBlend(none, candidates, 2, Eigen::Vector3d::Zero(), 0.01, &projected,
                                &normal));
}

TEST(SphereProjection, ASurfaceThatMovesThePointElsewhereBarelyCounts) {
  // Four planes within 0.7 of each other and one 30 away (the other side of a thin part, a
  // poor fit): the plain mean lands near z = 6; at a scale of 0.2^2 the blend stays within
  // 0.05 of the four's mean, 0.0625.
  const std::vector<LocalSurface> surfaces = HorizontalPlanes({0.1, -0.3, 0.05, 0.4, 30.0});
  const int candidates[] = {2, 0, 4, 3, 1};
  Eigen::Vector3d projected, normal;
  ASSERT_TRUE(ProjectOntoBlend(surfaces, candidates, 5, Eigen::Vector3d(0.7, -1.2, 0.2), 0.04,
                               &projected, &normal));
  EXPECT_NEAR(projected.x(), 0.7, 1e-15);
  EXPECT_NEAR(projected.y(), -1.2, 1e-15);
  EXPECT_NEAR(projected.z(), 0.0625, 0.05);
  ASSERT_TRUE(ProjectOntoBlend(surfaces, candidates, 5, Eigen::Vector3d(0.7, -1.2, 0.2), 0.0,
                               &projected, &normal));
  EXPECT_NEAR(projected.z(), 6.05, 1e-12);
}

TEST(SphereProjection, TheAgreementScaleIsTheMedianSquaredMoveOntoTheOwnSurface) {
  // Points at heights 0.1, -0.3, 0.02, 0.5 and 0.2 above the plane z = 0 (one point without a
  // surface): the moves squared are 0.01, 0.09, 0.0004 and 0.25; their upper median is 0.09.
  energy::Problem problem;
  const double heights[] = {0.1, -0.3, 0.02, 0.5, 0.2};
  for (double z : heights) problem.points.emplace_back(0.3, -0.1, z);
  std::vector<LocalSurface> surfaces = HorizontalPlanes({0.0, 0.0, 0.0, 0.0, 0.0});
  surfaces[4].kind = LocalSurface::Kind::kNone;
  EXPECT_NEAR(BlendAgreementScale(problem, surfaces), kBlendAgreement * kBlendAgreement * 0.09,
              1e-15);
  EXPECT_EQ(BlendAgreementScale(problem, std::vector<LocalSurface>(5)), 0.0);
}

TEST(SphereProjection, BlendingNeighboursSurfacesAveragesTheirNoiseFurther) {
  constexpr double kOffsetNoise = 0.002;
  const DisplacedSphere exact = MakeDisplacedSphere(4000, 0.01, 0.0);
  const DisplacedSphere noisy = MakeDisplacedSphere(4000, 0.01, kOffsetNoise);
  energy::PointList own, blended, normals;
  // Identical spheres blend into the same sphere.
  const std::vector<LocalSurface> exact_spheres =
      FitLocalSpheres(exact.problem, exact.variables, 2);
  ProjectOntoBlendedSurfaces(exact.problem, exact_spheres, 30,
                             BlendAgreementScale(exact.problem, exact_spheres), false, 2,
                             &blended, &normals);
  EXPECT_LT(LargestDistanceToTheSphere(blended), 1e-9);
  const std::vector<LocalSurface> spheres = FitLocalSpheres(noisy.problem, noisy.variables, 2);
  ProjectOntoBlendedSurfaces(noisy.problem, spheres, 1, 0.0, false, 2, &own, &normals);
  ProjectOntoBlendedSurfaces(noisy.problem, spheres, 30,
                             BlendAgreementScale(noisy.problem, spheres), false, 2, &blended,
                             &normals);
  // Measured: RMS 0.604e-3 alone, 0.527e-3 blending 5, 0.461e-3 blending all 11 (k = 10).
  EXPECT_LT(RmsDistanceToTheSphere(blended), 0.85 * RmsDistanceToTheSphere(own));
}

TEST(SphereProjection, TheSettledBlendLiesOnTheSurfacesMeanHeight) {
  // The plane z = 0 and the unit sphere whose top is at z = 0.05, blended as a plain mean:
  // over x (y = 0) their mean surface is z(x) = (0.05 - 1 + sqrt(1 - x^2)) / 2. From a point
  // 0.2 above or below it, the plain blend averages two nearest points that lie apart along
  // the surface and lands off z(x) (by 2.8e-3 and 7.4e-3); settled, within a fifth of that.
  std::vector<LocalSurface> surfaces = HorizontalPlanes({0.0, 0.0});
  surfaces[1].kind = LocalSurface::Kind::kSphere;
  surfaces[1].center = Eigen::Vector3d(0.0, 0.0, 0.05 - 1.0);
  surfaces[1].radius = 1.0;
  const int candidates[] = {0, 1};
  auto off_the_mean = [](const Eigen::Vector3d& q) {
    return std::abs(q.z() - (0.05 - 1.0 + std::sqrt(1.0 - q.x() * q.x())) / 2.0);
  };
  for (double height : {-0.2, 0.2}) {
    const Eigen::Vector3d p(0.3, 0.0, height);
    Eigen::Vector3d plain, settled, plain_normal, settled_normal;
    ASSERT_TRUE(ProjectOntoBlend(surfaces, candidates, 2, p, 0.0, &plain, &plain_normal));
    ASSERT_TRUE(
        ProjectOntoSettledBlend(surfaces, candidates, 2, p, 0.0, &settled, &settled_normal));
    EXPECT_GT(off_the_mean(plain), 2e-3) << "height " << height;
    EXPECT_LT(off_the_mean(settled), 0.2 * off_the_mean(plain)) << "height " << height;
    EXPECT_NEAR(settled.y(), 0.0, 1e-15);
    EXPECT_NEAR((settled_normal - plain_normal).norm(), 0.0, 1e-15);  // the first normal
  }
  // One surface: the plain projection.
  Eigen::Vector3d plain, settled, normal;
  const Eigen::Vector3d p(0.3, 0.1, 0.2);
  ASSERT_TRUE(ProjectOntoBlend(surfaces, candidates + 1, 1, p, 0.0, &plain, &normal));
  ASSERT_TRUE(ProjectOntoSettledBlend(surfaces, candidates + 1, 1, p, 0.0, &settled, &normal));
  EXPECT_EQ(plain, settled);
}

TEST(SphereProjection, SettlingKeepsPointsOnSurfacesThatAgree) {
  const DisplacedSphere sphere = MakeDisplacedSphere(2000, 0.01, 0.0);
  const std::vector<LocalSurface> spheres = FitLocalSpheres(sphere.problem, sphere.variables, 2);
  energy::PointList settled, normals;
  ProjectOntoBlendedSurfaces(sphere.problem, spheres, 30,
                             BlendAgreementScale(sphere.problem, spheres), true, 2, &settled,
                             &normals);
  EXPECT_LT(LargestDistanceToTheSphere(settled), 1e-9);
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
  ProjectOntoBlendedSurfaces(sphere.problem, FitLocalSpheres(sphere.problem, sphere.variables, 1),
                             1, 0.0, false, 1, &projected, &normals);
  EXPECT_LT(std::abs(projected[0].norm() - kRadius), 1e-9);
  sphere.variables.m[pair] = 1.0;  // with the pair kept, the tilted plane pulls the fit off
  ProjectOntoBlendedSurfaces(sphere.problem, FitLocalSpheres(sphere.problem, sphere.variables, 1),
                             1, 0.0, false, 1, &projected, &normals);
  EXPECT_GT(std::abs(projected[0].norm() - kRadius), 1e-6);
}

}  // namespace
}  // namespace lpd::solvers
