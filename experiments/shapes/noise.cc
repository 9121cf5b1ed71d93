#include "experiments/shapes/noise.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "energy/normalization.h"

namespace lpd::experiments {

using energy::Point3;
using energy::PointList;

bool NoiseOptions::IsValid(std::string* error) const {
  if (!(sigma >= 0.0 && std::isfinite(sigma))) {
    *error = "noise sigma must be a finite number >= 0";
  } else if (outlier_count < 0) {
    *error = "outlier count must be >= 0";
  } else if (!(outlier_ratio >= 0.0 && outlier_ratio <= 10.0)) {
    *error = "outlier ratio must be in [0, 10]";
  } else if (!(outlier_margin >= 0.0 && outlier_margin <= 1.0)) {
    *error = "outlier margin must be in [0, 1]";
  } else {
    return true;
  }
  return false;
}

std::string ToString(NoiseModel model) {
  switch (model) {
    case NoiseModel::kGaussian: return "gaussian";
    case NoiseModel::kNormal: return "normal";
    case NoiseModel::kVarying: return "varying";
  }
  return "?";
}

std::string ToString(NoiseScale scale) {
  switch (scale) {
    case NoiseScale::kBoundingBoxDiagonal: return "bbox_diagonal";
    case NoiseScale::kFpsDiameter: return "fps_diameter";
    case NoiseScale::kUnitSphereRadius: return "unit_sphere_radius";
  }
  return "?";
}

NoiseModel ParseNoiseModel(const std::string& name) {
  for (NoiseModel model : {NoiseModel::kGaussian, NoiseModel::kNormal, NoiseModel::kVarying}) {
    if (name == ToString(model)) return model;
  }
  throw std::invalid_argument("unknown noise model '" + name +
                              "' (expected gaussian, normal or varying)");
}

NoiseScale ParseNoiseScale(const std::string& name) {
  for (NoiseScale scale : {NoiseScale::kBoundingBoxDiagonal, NoiseScale::kFpsDiameter,
                           NoiseScale::kUnitSphereRadius}) {
    if (name == ToString(scale)) return scale;
  }
  throw std::invalid_argument("unknown noise scale '" + name +
                              "' (expected bbox_diagonal, fps_diameter or unit_sphere_radius)");
}

double FpsDiameter(const PointList& points) {
  if (points.size() < 2) return 0.0;
  size_t from = 0;
  double diameter = 0.0;
  for (int jump = 0; jump < 16; ++jump) {
    size_t farthest = from;
    double best = 0.0;
    for (size_t i = 0; i < points.size(); ++i) {
      const double d = (points[i] - points[from]).squaredNorm();
      if (d > best) {
        best = d;
        farthest = i;
      }
    }
    if (std::sqrt(best) <= diameter) break;
    diameter = std::sqrt(best);
    from = farthest;
  }
  return diameter;
}

UnitSphere UnitSphereOf(const PointList& points) {
  if (points.empty()) throw std::invalid_argument("no points to normalize");
  energy::Point3 low = points.front(), high = points.front();
  for (const energy::Point3& p : points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  UnitSphere sphere;
  sphere.centre = 0.5 * (low + high);
  for (const energy::Point3& p : points) {
    sphere.radius = std::max(sphere.radius, (p - sphere.centre).norm());
  }
  if (!(sphere.radius > 0.0)) throw std::invalid_argument("the points have no extent");
  return sphere;
}

double ScaleLength(const PointList& points, NoiseScale scale) {
  switch (scale) {
    case NoiseScale::kBoundingBoxDiagonal: return energy::BoundingBoxDiagonal(points);
    case NoiseScale::kFpsDiameter: return FpsDiameter(points);
    case NoiseScale::kUnitSphereRadius: return UnitSphereOf(points).radius;
  }
  return 0.0;
}

NoisyPointSet ApplyNoise(const PointList& clean, const PointList& normals,
                         const NoiseOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument(error);
  if (clean.empty()) throw std::invalid_argument("cannot add noise to an empty point set");
  if (options.model == NoiseModel::kNormal && normals.size() != clean.size()) {
    throw std::invalid_argument("normal-only noise needs one normal per clean point");
  }
  NoisyPointSet noisy;
  noisy.scale_length = ScaleLength(clean, options.scale);
  noisy.sigma_absolute = options.sigma * noisy.scale_length;
  noisy.points = clean;
  std::mt19937_64 rng(options.seed);
  std::normal_distribution<double> standard(0.0, 1.0);

  Point3 lo = clean.front(), hi = clean.front();
  for (const Point3& p : clean) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  int long_axis = 0;
  (hi - lo).maxCoeff(&long_axis);
  const double extent = hi[long_axis] - lo[long_axis];
  for (size_t i = 0; i < clean.size(); ++i) {
    Point3& p = noisy.points[i];
    switch (options.model) {
      case NoiseModel::kGaussian:
        for (int c = 0; c < 3; ++c) p[c] += noisy.sigma_absolute * standard(rng);
        break;
      case NoiseModel::kNormal:
        p += noisy.sigma_absolute * standard(rng) * normals[i].normalized();
        break;
      case NoiseModel::kVarying: {
        const double t = extent > 0.0 ? (clean[i][long_axis] - lo[long_axis]) / extent : 0.5;
        const double sigma = noisy.sigma_absolute * (0.5 + t);
        for (int c = 0; c < 3; ++c) p[c] += sigma * standard(rng);
        break;
      }
    }
  }
  noisy.is_outlier.assign(clean.size(), 0);

  const long num_outliers =
      options.outlier_count + std::lround(options.outlier_ratio * clean.size());
  const double pad = options.outlier_margin * (hi - lo).norm();
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (long n = 0; n < num_outliers; ++n) {
    Point3 p;
    for (int c = 0; c < 3; ++c) p[c] = lo[c] - pad + unit(rng) * (hi[c] - lo[c] + 2.0 * pad);
    noisy.points.push_back(p);
    noisy.is_outlier.push_back(1);
  }
  return noisy;
}

}  // namespace lpd::experiments
