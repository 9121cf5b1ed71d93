// Noise models: the measured sigma is the requested one, normal noise stays on the normal,
// varying noise varies as stated, outliers are counted, placed and labelled, and the FPS
// diameter agrees with brute force.
#include "experiments/shapes/noise.h"

#include <cmath>

#include <gtest/gtest.h>

#include "energy/normalization.h"
#include "experiments/shapes/shape_catalog.h"

namespace lpd::experiments {
namespace {

using energy::Point3;
using energy::PointList;

double BruteForceDiameter(const PointList& points) {
  double best = 0.0;
  for (const Point3& a : points) {
    for (const Point3& b : points) best = std::max(best, (a - b).norm());
  }
  return best;
}

TEST(Noise, FpsDiameterIsCloseToTheBruteForceDiameter) {
  for (const char* name : {"cube", "cad_part", "cone"}) {
    const PointList points = MakeShape({name, {}}).Sample(1500, 1).points;
    const double brute = BruteForceDiameter(points);
    const double fps = FpsDiameter(points);
    EXPECT_LE(fps, brute + 1e-12) << name;
    EXPECT_GE(fps, 0.99 * brute) << name;
  }
}

TEST(Noise, IsotropicSigmaIsWhatWasAskedForOnBothScales) {
  const SurfaceSamples clean = MakeShape({"cad_part", {}}).Sample(100000, 2);
  for (NoiseScale scale : {NoiseScale::kBoundingBoxDiagonal, NoiseScale::kFpsDiameter}) {
    NoiseOptions options;
    options.sigma = 0.02;
    options.scale = scale;
    const NoisyPointSet noisy = ApplyNoise(clean.points, clean.normals, options);
    const double length = scale == NoiseScale::kBoundingBoxDiagonal
                              ? energy::BoundingBoxDiagonal(clean.points)
                              : FpsDiameter(clean.points);
    EXPECT_DOUBLE_EQ(noisy.scale_length, length);
    double sum_squared = 0.0;
    for (size_t i = 0; i < clean.points.size(); ++i) {
      sum_squared += (noisy.points[i] - clean.points[i]).squaredNorm();
    }
    const double measured = std::sqrt(sum_squared / (3.0 * clean.points.size()));
    EXPECT_NEAR(measured / (0.02 * length), 1.0, 0.03) << ToString(scale);
  }
}

TEST(Noise, NormalNoiseMovesPointsAlongTheirNormalsOnly) {
  const SurfaceSamples clean = MakeShape({"sphere", {}}).Sample(50000, 3);
  NoiseOptions options;
  options.model = NoiseModel::kNormal;
  options.sigma = 0.01;
  const NoisyPointSet noisy = ApplyNoise(clean.points, clean.normals, options);
  double sum_squared = 0.0;
  for (size_t i = 0; i < clean.points.size(); ++i) {
    const Point3 displacement = noisy.points[i] - clean.points[i];
    ASSERT_LT(displacement.cross(clean.normals[i]).norm(), 1e-12);
    sum_squared += displacement.squaredNorm();
  }
  EXPECT_NEAR(std::sqrt(sum_squared / clean.points.size()) / noisy.sigma_absolute, 1.0, 0.03);
  EXPECT_THROW(ApplyNoise(clean.points, {}, options), std::invalid_argument);
}

TEST(Noise, VaryingNoiseGrowsAlongTheLongestAxis) {
  // Box 1 x 0.8 x 0.6: sigma runs from 0.5 to 1.5 times the base along x.
  const SurfaceSamples clean = MakeShape({"box", {}}).Sample(200000, 4);
  NoiseOptions options;
  options.model = NoiseModel::kVarying;
  options.sigma = 0.01;
  const NoisyPointSet noisy = ApplyNoise(clean.points, clean.normals, options);
  double low = 0.0, high = 0.0;
  long low_count = 0, high_count = 0;
  for (size_t i = 0; i < clean.points.size(); ++i) {
    const double squared = (noisy.points[i] - clean.points[i]).squaredNorm() / 3.0;
    if (clean.points[i].x() < -0.45) {
      low += squared;
      ++low_count;
    }
    if (clean.points[i].x() > 0.45) {
      high += squared;
      ++high_count;
    }
  }
  // Within 5% of the ends the expected factor is 0.5..0.55 and 1.45..1.5.
  EXPECT_NEAR(std::sqrt(low / low_count) / noisy.sigma_absolute, 0.525, 0.03);
  EXPECT_NEAR(std::sqrt(high / high_count) / noisy.sigma_absolute, 1.475, 0.05);
}

TEST(Noise, OutliersAreCountedPlacedAndLabelled) {
  const SurfaceSamples clean = MakeShape({"cube", {}}).Sample(10000, 5);
  NoiseOptions options;
  options.sigma = 0.0;
  options.outlier_count = 100;
  options.outlier_ratio = 0.02;
  options.outlier_margin = 0.1;
  const NoisyPointSet noisy = ApplyNoise(clean.points, clean.normals, options);
  ASSERT_EQ(noisy.points.size(), 10000u + 100u + 200u);
  ASSERT_EQ(noisy.is_outlier.size(), noisy.points.size());
  const double pad = 0.1 * std::sqrt(3.0);
  for (size_t i = 0; i < noisy.points.size(); ++i) {
    ASSERT_EQ(noisy.is_outlier[i], i >= 10000 ? 1 : 0);
    if (i < 10000) {
      ASSERT_EQ(noisy.points[i], clean.points[i]);
    }
    ASSERT_LE(noisy.points[i].cwiseAbs().maxCoeff(), 0.5 + pad + 1e-9);
  }
}

TEST(Noise, SeedsReproduceAndBadOptionsAreRefused) {
  const SurfaceSamples clean = MakeShape({"cube", {}}).Sample(1000, 6);
  NoiseOptions options;
  options.outlier_count = 10;
  EXPECT_EQ(ApplyNoise(clean.points, {}, options).points,
            ApplyNoise(clean.points, {}, options).points);
  NoiseOptions other = options;
  other.seed = 2;
  EXPECT_NE(ApplyNoise(clean.points, {}, options).points,
            ApplyNoise(clean.points, {}, other).points);
  options.sigma = -1.0;
  EXPECT_THROW(ApplyNoise(clean.points, {}, options), std::invalid_argument);
  EXPECT_THROW(ParseNoiseModel("pink"), std::invalid_argument);
  EXPECT_THROW(ParseNoiseScale("radius"), std::invalid_argument);
}

}  // namespace
}  // namespace lpd::experiments
