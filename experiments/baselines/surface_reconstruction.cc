#include "experiments/baselines/surface_reconstruction.h"

#include <array>
#include <iterator>
#include <stdexcept>
#include <vector>

#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Scale_space_reconstruction_3/Advancing_front_mesher.h>
#include <CGAL/Scale_space_reconstruction_3/Jet_smoother.h>
#include <CGAL/Scale_space_surface_reconstruction_3.h>

#include <Eigen/Eigenvalues>

#include "experiments/baselines/cgal_points.h"

namespace lpd::experiments {
namespace {

// Points along one line (or all at one place) span no surface, and CGAL's Delaunay-based
// meshers fail on them without a clean error: true when the covariance's second eigenvalue
// vanishes next to its largest.
bool SpanAtMostALine(const energy::PointList& points) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const energy::Point3& p : points) mean += p;
  mean /= points.size();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const energy::Point3& p : points) covariance += (p - mean) * (p - mean).transpose();
  const Eigen::Vector3d eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance, Eigen::EigenvaluesOnly)
          .eigenvalues();  // increasing
  return !(eigenvalues(1) > 1e-12 * eigenvalues(2));
}

using Facet = std::array<std::size_t, 3>;

std::vector<Facet> AdvancingFrontFacets(const std::vector<cgal::Point>& points) {
  std::vector<Facet> facets;
  CGAL::advancing_front_surface_reconstruction(points.begin(), points.end(),
                                               std::back_inserter(facets));
  return facets;
}

std::vector<Facet> ScaleSpaceFacets(const std::vector<cgal::Point>& points, int iterations) {
  CGAL::Scale_space_surface_reconstruction_3<cgal::Kernel> reconstruction(points.begin(),
                                                                          points.end());
  if (iterations > 0) {
    reconstruction.increase_scale(iterations,
                                  CGAL::Scale_space_reconstruction_3::Jet_smoother<cgal::Kernel>());
  }
  // The smoothed points keep their order, so the facets index the original points.
  reconstruction.reconstruct_surface(
      CGAL::Scale_space_reconstruction_3::Advancing_front_mesher<cgal::Kernel>());
  return std::vector<Facet>(reconstruction.facets_begin(), reconstruction.facets_end());
}

}  // namespace

std::string ToString(Reconstruction method) {
  return method == Reconstruction::kAdvancingFront ? "advancing_front" : "scale_space";
}

Reconstruction ParseReconstruction(const std::string& name) {
  if (name == "advancing_front") return Reconstruction::kAdvancingFront;
  if (name == "scale_space") return Reconstruction::kScaleSpace;
  throw std::invalid_argument("reconstruction: '" + name +
                              "' is not one of advancing_front, scale_space");
}

TriangleMesh ReconstructSurface(const energy::PointList& points,
                                const ReconstructionOptions& options) {
  if (points.size() < 4) {
    throw std::invalid_argument("reconstruction needs at least 4 points, got " +
                                std::to_string(points.size()));
  }
  if (SpanAtMostALine(points)) {
    throw std::invalid_argument("the points are collinear or coincide: no surface through them");
  }
  if (options.scale_iterations < 0) {
    throw std::invalid_argument("scale_iterations must be >= 0");
  }
  const std::vector<cgal::Point> cgal_points = cgal::ToCgal(points);
  const std::vector<Facet> facets =
      options.method == Reconstruction::kAdvancingFront
          ? AdvancingFrontFacets(cgal_points)
          : ScaleSpaceFacets(cgal_points, options.scale_iterations);
  if (facets.empty()) throw std::runtime_error("reconstruction produced no triangle");
  TriangleMesh mesh;
  mesh.vertices = points;
  mesh.triangles.reserve(facets.size());
  for (const Facet& f : facets) {
    mesh.triangles.push_back({static_cast<int>(f[0]), static_cast<int>(f[1]),
                              static_cast<int>(f[2])});
  }
  return mesh;
}

}  // namespace lpd::experiments
