// The CGAL baselines: each one denoises a noisy plane (checked against the exact plane),
// WLOP keeps the requested share of points, and invalid options are refused. A plane, not a
// sphere: on a coarsely sampled sphere bilateral smoothing drifts outward and WLOP inward
// (mean radial offsets +0.016 and -0.016 at 3,000 points), biases of the methods that would
// hide whether they remove noise.
#include "experiments/baselines/cgal_baselines.h"

#include <stdexcept>

#include <gtest/gtest.h>

#include "test_problems.h"

namespace lpd::experiments {
namespace {

// Mean distance to the plane z = 0 of test_problems.h.
double MeanPlaneDistance(const energy::PointList& points) {
  double sum = 0.0;
  for (const energy::Point3& p : points) sum += std::abs(p.z());
  return sum / points.size();
}

class CgalBaselines : public ::testing::Test {
 protected:
  const energy::PointList noisy_ = testing::NoisyPlane(3000, 0.005, 3);
  const double input_distance_ = MeanPlaneDistance(noisy_);
};

TEST_F(CgalBaselines, BilateralWithPcaOrJetNormalsHalveTheNoiseOnAPlane) {
  for (NormalEstimator normals : {NormalEstimator::kPca, NormalEstimator::kJet}) {
    BilateralOptions options;
    options.k = 30;
    options.normals = normals;
    const energy::PointList smoothed = BilateralSmooth(noisy_, options);
    ASSERT_EQ(smoothed.size(), noisy_.size());
    EXPECT_LT(MeanPlaneDistance(smoothed), 0.5 * input_distance_) << ToString(normals);
  }
}

TEST_F(CgalBaselines, JetSmoothingHalvesTheNoiseOnAPlane) {
  JetOptions options;
  options.k = 30;
  const energy::PointList smoothed = JetSmooth(noisy_, options);
  ASSERT_EQ(smoothed.size(), noisy_.size());
  EXPECT_LT(MeanPlaneDistance(smoothed), 0.5 * input_distance_);
}

TEST_F(CgalBaselines, WlopKeepsTheRequestedShareAndHalvesItsNoise) {
  WlopOptions options;
  options.select_percentage = 25.0;
  options.iterations = 10;
  const energy::PointList resampled = WlopResample(noisy_, options);
  EXPECT_EQ(resampled.size(), noisy_.size() / 4);
  EXPECT_LT(MeanPlaneDistance(resampled), 0.5 * input_distance_);
}

TEST_F(CgalBaselines, RefuseInvalidOptions) {
  BilateralOptions bilateral;
  bilateral.k = static_cast<int>(noisy_.size());
  EXPECT_THROW(BilateralSmooth(noisy_, bilateral), std::invalid_argument);
  JetOptions jet;
  jet.k = 4;
  EXPECT_THROW(JetSmooth(noisy_, jet), std::invalid_argument);
  WlopOptions wlop;
  wlop.select_percentage = 0.0;
  EXPECT_THROW(WlopResample(noisy_, wlop), std::invalid_argument);
  EXPECT_THROW(ParseNormalEstimator("vcm"), std::invalid_argument);
}

}  // namespace
}  // namespace lpd::experiments
