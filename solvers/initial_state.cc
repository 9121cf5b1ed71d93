#include "solvers/initial_state.h"

#include <cmath>
#include <random>
#include <stdexcept>

#include "energy/fitting_term.h"
#include "energy/smoothness_term.h"
#include "solvers/local_plane_fit.h"
#include "solvers/parse_by_name.h"

namespace lpd::solvers {
namespace {

void RandomPlanes(uint64_t seed, energy::PlaneField* h) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> gaussian;
  for (Eigen::Index i = 0; i < h->rows(); ++i) {
    Eigen::Vector4d plane;
    do {
      for (int c = 0; c < 4; ++c) plane[c] = gaussian(random);
    } while (plane.squaredNorm() == 0.0);
    h->row(i) = plane.normalized().transpose();  // isotropic, so uniform on the sphere
  }
}

void PlanesFromNormals(const energy::Problem& problem, const energy::PointList* normals,
                       energy::PlaneField* h) {
  const int n = problem.num_points();
  if (!normals || static_cast<int>(normals->size()) != n) {
    throw std::invalid_argument(
        "initialization input_normals needs one normal per point (a PLY input with nx, ny, "
        "nz)");
  }
  for (int i = 0; i < n; ++i) {
    const energy::Point3& normal = (*normals)[i];
    if (!normal.allFinite() || normal.squaredNorm() == 0.0) {
      throw std::invalid_argument("initialization input_normals: the normal of point " +
                                  std::to_string(i) + " is zero or not finite");
    }
    const Eigen::Vector3d unit = normal.normalized();
    Eigen::Vector4d plane(unit.x(), unit.y(), unit.z(), -unit.dot(problem.points[i]));
    h->row(i) = plane.normalized().transpose();
  }
}

}  // namespace

const char* InitializationName(Initialization initialization) {
  switch (initialization) {
    case Initialization::kZero: return "zero";
    case Initialization::kPlaneFit: return "plane_fit";
    case Initialization::kRandom: return "random";
    case Initialization::kInputNormals: return "input_normals";
  }
  return "zero";
}

bool ParseInitialization(const std::string& name, Initialization* initialization) {
  constexpr Initialization kInitializations[] = {
      Initialization::kZero, Initialization::kPlaneFit, Initialization::kRandom,
      Initialization::kInputNormals};
  return ParseByName(name, kInitializations, InitializationName, initialization);
}

energy::Variables InitialState(const energy::Problem& problem,
                               const energy::EnergyParameters& parameters,
                               Initialization initialization, int num_threads, uint64_t seed,
                               const energy::PointList* normals) {
  energy::Variables v = energy::InitialVariables(problem, num_threads);
  switch (initialization) {
    case Initialization::kZero: return v;
    case Initialization::kPlaneFit:
      UpdateLocalPlanes(problem, parameters, num_threads, &v);  // PCA planes: l = 1, t = 0
      break;
    case Initialization::kRandom: RandomPlanes(seed, &v.h); break;
    case Initialization::kInputNormals: PlanesFromNormals(problem, normals, &v.h); break;
  }
  v.t = v.h;
  const energy::SmoothnessTerm smoothness(problem, parameters.lambda, parameters.mu_m,
                                          num_threads);
  smoothness.UpdateOrientations(&v);
  smoothness.UpdateLineProcesses(&v);
  energy::FittingTerm(problem, parameters.mu_l, num_threads).UpdateLineProcesses(&v);
  return v;
}

}  // namespace lpd::solvers
