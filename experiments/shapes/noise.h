// lpd: seeded noise and outlier models for synthetic inputs.
//
// The noise level is a fraction of a length scale of the clean model: its bounding-box
// diagonal, its diameter as estimated by farthest-point sampling (the paper's Fig. 13 and
// Fig. 17 convention, after [ZCN*19]), or the radius of its unit sphere (the learned
// denoisers' benchmark, benchmark_metrics.h). Every noisy set records which scale it used, the
// absolute sigma, and which of its points are outliers.
#ifndef LPD_EXPERIMENTS_SHAPES_NOISE_H_
#define LPD_EXPERIMENTS_SHAPES_NOISE_H_

#include <cstdint>
#include <string>
#include <vector>

#include "energy/normalization.h"

namespace lpd::experiments {

enum class NoiseModel {
  kGaussian,  // isotropic: N(0, sigma^2) on each coordinate
  kNormal,    // N(0, sigma^2) along the clean surface normal only
  kVarying,   // isotropic, sigma growing linearly from 0.5 to 1.5 times the given sigma along
              // the longest bounding-box axis (mean sigma for evenly spread points)
};

enum class NoiseScale { kBoundingBoxDiagonal, kFpsDiameter, kUnitSphereRadius };

struct NoiseOptions {
  NoiseModel model = NoiseModel::kGaussian;
  double sigma = 0.01;  // fraction of the scale length
  NoiseScale scale = NoiseScale::kBoundingBoxDiagonal;
  // Uniform outliers in the bounding box enlarged by `outlier_margin` times its diagonal on
  // every side: `outlier_count` of them, plus `outlier_ratio` times the clean point count.
  int outlier_count = 0;
  double outlier_ratio = 0.0;
  double outlier_margin = 0.05;
  uint64_t seed = 1;

  bool IsValid(std::string* error) const;
};

struct NoisyPointSet {
  energy::PointList points;          // the noisy clean points first, then the outliers
  std::vector<uint8_t> is_outlier;   // one label per point
  double scale_length = 0.0;         // the length sigma is a fraction of
  double sigma_absolute = 0.0;       // sigma in the model's units
};

// Names used in configs, CSV files and flags: "gaussian", "normal", "varying";
// "bbox_diagonal", "fps_diameter", "unit_sphere_radius". The parsers throw std::invalid_argument on unknown names.
std::string ToString(NoiseModel model);
std::string ToString(NoiseScale scale);
NoiseModel ParseNoiseModel(const std::string& name);
NoiseScale ParseNoiseScale(const std::string& name);

// Diameter estimate by farthest-point sampling: from point 0, jump to the farthest point, then
// to the farthest from that one, until the distance stops growing. A lower bound of the true
// diameter, and at least half of it; exact for most convex shapes after two jumps.
double FpsDiameter(const energy::PointList& points);

// The sphere the learned denoisers' benchmark normalizes by: centre (max + min) / 2 of the
// points, radius the largest distance of a point from it. Throws std::invalid_argument if
// `points` is empty or all one point.
struct UnitSphere {
  energy::Point3 centre = energy::Point3::Zero();
  double radius = 0.0;
};
UnitSphere UnitSphereOf(const energy::PointList& points);

double ScaleLength(const energy::PointList& points, NoiseScale scale);

// Applies `options` to `clean`. `normals` (one per point) are needed by the normal-only model
// and ignored otherwise. Throws std::invalid_argument on invalid options.
NoisyPointSet ApplyNoise(const energy::PointList& clean, const energy::PointList& normals,
                         const NoiseOptions& options);

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_SHAPES_NOISE_H_
