// A test fixture: points on a sphere with tangent planes, for the projections' closed forms.
#ifndef LPD_TESTS_SOLVERS_DISPLACED_SPHERE_H_
#define LPD_TESTS_SOLVERS_DISPLACED_SPHERE_H_

#include <random>

#include "energy/neighbor_graph.h"
#include "energy/problem.h"
#include "energy/variables.h"

namespace lpd::solvers {

inline constexpr double kRadius = 0.3;

// Points on a sphere of radius kRadius about the origin, each moved along its normal by a
// Gaussian of deviation `radial`; t_i is the tangent plane at the point it came from, moved
// along the normal by a Gaussian of deviation `plane_offset`. Identity frame.
struct DisplacedSphere {
  energy::Problem problem;
  energy::Variables variables;
};

inline DisplacedSphere MakeDisplacedSphere(int n, double radial, double plane_offset) {
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

}  // namespace lpd::solvers

#endif  // LPD_TESTS_SOLVERS_DISPLACED_SPHERE_H_
