// lpd: an axis-aligned box as a procedural ground-truth shape with sharp edges.
//
// Exact surface: area-uniform sampling of the six faces, the exact unsigned distance of any
// point to the surface, and the distance to the nearest of the twelve edges (for scoring
// feature detection). Used as the built-in default input of `lpd denoise`.
#ifndef LPD_EXPERIMENTS_BOX_SHAPE_H_
#define LPD_EXPERIMENTS_BOX_SHAPE_H_

#include <random>

#include "energy/normalization.h"

namespace lpd::experiments {

class BoxShape {
 public:
  // The box [center - half_extents, center + half_extents]; half extents must be > 0.
  BoxShape(const energy::Point3& center, const energy::Point3& half_extents);

  // `count` points drawn uniformly by area from the surface.
  energy::PointList SampleSurface(int count, std::mt19937_64* rng) const;

  // Exact Euclidean distance from `p` to the box surface (inside or outside).
  double DistanceToSurface(const energy::Point3& p) const;

  // Euclidean distance from `p` to the nearest edge of the box.
  double DistanceToEdges(const energy::Point3& p) const;

  double Diagonal() const { return 2.0 * half_extents_.norm(); }
  energy::Point3 Size() const { return 2.0 * half_extents_; }

 private:
  energy::Point3 center_;
  energy::Point3 half_extents_;
};

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_BOX_SHAPE_H_
