// lpd: what a denoised point set is scored against.
//
// A ground truth is a dense, seeded sample of the clean surface (for the symmetric MSE, MCD
// and SNR of [ZCN*19]), the model's bounding-box diagonal (for normalized figures), and, when
// known, the exact point-to-surface distance and the distance to the sharp features.
#ifndef LPD_EXPERIMENTS_EVALUATION_GROUND_TRUTH_H_
#define LPD_EXPERIMENTS_EVALUATION_GROUND_TRUTH_H_

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "energy/point3.h"
#include "experiments/shapes/procedural_shape.h"
#include "experiments/shapes/triangle_mesh.h"

namespace lpd::experiments {

struct GroundTruth {
  std::string description;  // what it is and how it was sampled
  energy::PointList samples;
  double diagonal = 0.0;
  // Exact unsigned distances from points to the clean surface (empty when not known).
  std::function<std::vector<double>(const energy::PointList&, int num_threads)>
      surface_distances;
  // Distance from a point to the nearest sharp feature (empty when not known).
  std::function<double(const energy::Point3&)> feature_distance;
  // The other way: from each element of the clean surface (a mesh's triangles, a procedural
  // shape's dense samples) to the nearest of `points` (empty when not known).
  std::function<std::vector<double>(const energy::PointList&, int num_threads)>
      surface_to_points_distances;
  // The points that fix the unit-sphere frame of the benchmark figures: a mesh's vertices,
  // a procedural shape's dense samples (benchmark_metrics.h).
  energy::PointList frame_points;
};

// Dense samples of the clean surface: enough that their spacing (about 2e-3 of the diagonal
// on the catalogue's shapes) stays well below the noise levels scored.
constexpr int kGroundTruthSamples = 200000;
constexpr uint64_t kGroundTruthSeed = 20230501;

GroundTruth ShapeGroundTruth(std::shared_ptr<const ProceduralShape> shape,
                             int num_samples = kGroundTruthSamples,
                             uint64_t seed = kGroundTruthSeed);

// A clean point set as the ground truth (no exact surface: nearest-point distances only).
GroundTruth PointSetGroundTruth(energy::PointList points, const std::string& description);

// A triangle mesh (read with ReadTriangleMesh; `name` says where it came from): dense
// area-uniform samples plus exact distances with CGAL's AABB tree. Implemented in
// mesh_ground_truth.cc (the CGAL translation unit of lpd_evaluation).
GroundTruth MeshGroundTruth(const TriangleMesh& mesh, const std::string& name,
                            int num_samples = kGroundTruthSamples,
                            uint64_t seed = kGroundTruthSeed);

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_EVALUATION_GROUND_TRUTH_H_
