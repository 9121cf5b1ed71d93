// lpd: analytic surface patches that procedural ground-truth shapes are made of.
//
// Each patch knows its area, draws area-uniform samples with their outward unit normals, and
// gives the exact Euclidean distance from any point to itself. A shape is a union of patches,
// so its exact distance is the minimum over its patches.
#ifndef LPD_EXPERIMENTS_SHAPES_SURFACE_PATCHES_H_
#define LPD_EXPERIMENTS_SHAPES_SURFACE_PATCHES_H_

#include <random>
#include <vector>

#include "energy/point3.h"

namespace lpd::experiments {

struct SurfacePoint {
  energy::Point3 position;
  energy::Point3 normal;  // outward, unit length
};

class SurfacePatch {
 public:
  virtual ~SurfacePatch() = default;
  virtual double Area() const = 0;
  virtual SurfacePoint Sample(std::mt19937_64* rng) const = 0;
  virtual double Distance(const energy::Point3& p) const = 0;
};

// A planar convex polygon. `vertices` are in order around the boundary; the polygon is
// oriented so that its normal agrees with `outward` (the order is reversed if needed).
// Throws std::invalid_argument for fewer than three vertices or a zero-area polygon.
class ConvexPolygon final : public SurfacePatch {
 public:
  ConvexPolygon(std::vector<energy::Point3> vertices, const energy::Point3& outward);
  double Area() const override { return area_; }
  SurfacePoint Sample(std::mt19937_64* rng) const override;
  double Distance(const energy::Point3& p) const override;

 private:
  std::vector<energy::Point3> vertices_;
  energy::Point3 normal_;
  std::vector<double> fan_areas_;  // triangle (v0, v_t+1, v_t+2) areas
  double area_ = 0.0;
};

// A frame for surfaces of revolution: points are origin + z axis + r (cos t e1 + sin t e2)
// with e2 = axis x e1, for a unit `axis` and a unit `reference` e1 orthogonal to it.
struct RevolutionFrame {
  energy::Point3 origin = energy::Point3::Zero();
  energy::Point3 axis = energy::Point3::UnitZ();
  energy::Point3 reference = energy::Point3::UnitX();

  energy::Point3 At(double r, double z, double angle) const;
};

// The surface swept by the profile segment (r0, z0) -> (r1, z1) (r >= 0) turning about the
// frame's axis over the angles [start, start + sweep], sweep in (0, 2 pi]. A segment with
// r0 == r1 gives a cylinder piece, z0 == z1 a disk or annulus, otherwise a cone piece. The
// outward normal is the profile direction turned by -90 degrees in the (r, z) half-plane, so a
// profile that runs counterclockwise around a solid's cross-section gets outward normals.
class RevolvedSegment final : public SurfacePatch {
 public:
  RevolvedSegment(const RevolutionFrame& frame, double r0, double z0, double r1, double z1,
                  double start, double sweep);
  double Area() const override { return area_; }
  SurfacePoint Sample(std::mt19937_64* rng) const override;
  double Distance(const energy::Point3& p) const override;

 private:
  RevolutionFrame frame_;
  double r0_, z0_, r1_, z1_;
  double start_, sweep_;
  double area_ = 0.0;
};

class Sphere final : public SurfacePatch {
 public:
  Sphere(const energy::Point3& center, double radius);
  double Area() const override;
  SurfacePoint Sample(std::mt19937_64* rng) const override;
  double Distance(const energy::Point3& p) const override;

 private:
  energy::Point3 center_;
  double radius_;
};

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_SHAPES_SURFACE_PATCHES_H_
