// MeshGroundTruth (declared in ground_truth.h): CGAL-backed, so a translation unit of its own.
#include <sstream>

#include "energy/normalization.h"
#include "experiments/evaluation/ground_truth.h"
#include "experiments/evaluation/mesh_distance.h"

namespace lpd::experiments {

GroundTruth MeshGroundTruth(const TriangleMesh& mesh, const std::string& name, int num_samples,
                            uint64_t seed) {
  auto distance = std::make_shared<const MeshDistance>(mesh);
  GroundTruth truth;
  std::ostringstream description;
  description << name << " (" << mesh.triangles.size() << " triangles), " << num_samples
              << " samples, seed " << seed;
  truth.description = description.str();
  truth.samples = SampleTriangleMesh(mesh, num_samples, seed).points;
  truth.diagonal = distance->BoundingBoxDiagonal();
  truth.surface_distances = [distance](const energy::PointList& points, int num_threads) {
    return distance->Distances(points, num_threads);
  };
  truth.surface_to_points_distances = [distance](const energy::PointList& points,
                                                 int num_threads) {
    return distance->TriangleDistances(points, num_threads);
  };
  truth.frame_points = mesh.vertices;
  return truth;
}

}  // namespace lpd::experiments
