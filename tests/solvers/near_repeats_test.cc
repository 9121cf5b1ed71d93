// Near repeats: the representatives against a brute-force search, the share below which they
// are left alone, and a cloud given twice within a hair denoised as the single copy.
#include "solvers/near_repeats.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "lpd/presets.h"
#include "solvers/denoise_point_set.h"
#include "test_problems.h"

namespace lpd::solvers {
namespace {

using energy::Point3;
using energy::PointList;

// Appends a copy of points[i] moved by Gaussian jitter of `jitter` (per coordinate) for each
// of `count` randomly chosen i, in random order; returns the i.
std::vector<int> AppendJitteredCopies(int count, double jitter, uint64_t seed, PointList* points) {
  std::mt19937_64 random(seed);
  std::vector<int> chosen(points->size());
  std::iota(chosen.begin(), chosen.end(), 0);
  std::shuffle(chosen.begin(), chosen.end(), random);
  chosen.resize(count);
  std::normal_distribution<double> gaussian(0.0, jitter);
  for (int i : chosen) {
    const Point3 p = (*points)[i];
    points->push_back(p + Point3(gaussian(random), gaussian(random), gaussian(random)));
  }
  return chosen;
}

// The rule of near_repeats.h, computed from all pairwise distances.
std::vector<int> BruteForceRepresentatives(const PointList& points) {
  const int n = static_cast<int>(points.size());
  std::vector<int> representative(n);
  std::iota(representative.begin(), representative.end(), 0);
  int repeats = 0;
  for (int r = 0; r < n; ++r) {
    std::vector<std::pair<double, int>> by_distance;
    for (int j = 0; j < n; ++j) {
      if (j != r) by_distance.emplace_back((points[j] - points[r]).norm(), j);
    }
    std::sort(by_distance.begin(), by_distance.end());
    const double spacing =
        std::sqrt(M_PI / kNearRepeatNeighbors) * by_distance[kNearRepeatNeighbors - 1].first;
    for (const auto& [distance, j] : by_distance) {
      if (distance >= kNearRepeatRadius * spacing) break;
      if (j < r && representative[j] == j) {
        representative[r] = j;
        ++repeats;
        break;
      }
    }
  }
  if (repeats < kMinNearRepeatShare * n) std::iota(representative.begin(), representative.end(), 0);
  return representative;
}

TEST(NearRepeats, RepresentativesAgreeWithBruteForce) {
  PointList points = testing::NoisySphere(600, 0.01, 4);
  // Copies a hair away (spacing about 0.14), some of them copied again: chains of three.
  AppendJitteredCopies(150, 1e-4, 5, &points);
  AppendJitteredCopies(60, 2e-3, 6, &points);
  for (int threads : {1, 2}) {
    const std::vector<int> representative = NearRepeatRepresentatives(points, threads);
    const std::vector<int> expected = BruteForceRepresentatives(points);
    ASSERT_EQ(representative, expected) << threads << " threads";
    int merged = 0;
    for (size_t r = 0; r < points.size(); ++r) merged += representative[r] != static_cast<int>(r);
    EXPECT_GE(merged, 150);
  }
  // Coordinates whose squared distances overflow (or underflow) give the same.
  for (double scale : {1e200, 1e-200}) {
    PointList scaled = points;
    for (Point3& p : scaled) p *= scale;
    EXPECT_EQ(NearRepeatRepresentatives(scaled, 2), NearRepeatRepresentatives(points, 2)) << scale;
  }
}

TEST(NearRepeats, AreLeftAloneWhereTheyAreFewerThanTheShare) {
  PointList points = testing::NoisySphere(3000, 0.01, 7);
  auto merged = [](const PointList& cloud) {
    const std::vector<int> representative = NearRepeatRepresentatives(cloud, 2);
    int count = 0;
    for (size_t r = 0; r < cloud.size(); ++r) count += representative[r] != static_cast<int>(r);
    return count;
  };
  // A random sample of a surface, at noise far under the spacing, has its own close pairs:
  // about pi 0.1^2 / 2 = 1.6% of its points.
  EXPECT_EQ(merged(points), 0);
  PointList few = points;
  AppendJitteredCopies(60, 1e-5, 8, &few);  // with them, under 5% of the points
  EXPECT_EQ(merged(few), 0);
  PointList many = points;
  AppendJitteredCopies(150, 1e-5, 8, &many);
  EXPECT_GE(merged(many), 150);
}

// Past kNearRepeatSample points, an even sample decides whether to look at every point.
TEST(NearRepeats, InALargeCloudASampleFindsThemOrTheirAbsence) {
  const PointList plane = testing::NoisyPlane(40000, 0.01, 9);  // spacing 0.005
  const std::vector<int> alone = NearRepeatRepresentatives(plane, 2);
  for (int r = 0; r < static_cast<int>(plane.size()); ++r) ASSERT_EQ(alone[r], r);
  PointList doubled = plane;
  const std::vector<int> copied = AppendJitteredCopies(4000, 1e-6, 10, &doubled);
  const std::vector<int> representative = NearRepeatRepresentatives(doubled, 2);
  int merged_originals = 0;
  for (size_t r = 0; r < plane.size(); ++r) {
    merged_originals += representative[r] != static_cast<int>(r);
  }
  EXPECT_LT(merged_originals, 0.002 * plane.size());  // random close pairs
  for (size_t c = 0; c < copied.size(); ++c) {
    // The original's representative: the original, or the point it is a random close pair of.
    ASSERT_EQ(representative[plane.size() + c], representative[copied[c]]) << c;
  }
}

// `n` evenly spread points of the unit sphere (a Fibonacci lattice: no close pairs) moved
// along the normal by Gaussian noise `sigma`.
PointList NoisyFibonacciSphere(int n, double sigma, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> gaussian(0.0, sigma);
  const double golden_angle = M_PI * (3.0 - std::sqrt(5.0));
  PointList points;
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(1.0 - z * z);
    const Point3 p(r * std::cos(golden_angle * i), r * std::sin(golden_angle * i), z);
    points.push_back((1.0 + gaussian(random)) * p);
  }
  return points;
}

// The cloud followed by a copy moved by a thousandth of the spacing: the originals come out
// as the single copy's result, each copy as its original's moved along the surface.
TEST(NearRepeats, ACloudGivenTwiceWithinAHairIsDenoisedAsTheSingleCopy) {
  const PointList single = NoisyFibonacciSphere(3000, 0.01, 11);
  DenoiseOptions options = PresetOptions(Preset::kDefault);
  options.settings.num_threads = 2;
  options.minimizer.max_iterations = 15;
  const DenoiseResult alone = DenoisePointSet(single, options);
  ASSERT_EQ(alone.num_near_repeats, 0);

  PointList twice = single;
  const double jitter = 1e-4;  // the spacing is about 0.065
  const std::vector<int> copied = AppendJitteredCopies(3000, jitter, 12, &twice);
  twice.push_back(twice[3000]);  // an exact repeat of a near repeat
  const DenoiseResult result = DenoisePointSet(twice, options);
  EXPECT_EQ(result.num_near_repeats, 3000);
  EXPECT_EQ(result.num_duplicates, 1);
  EXPECT_EQ(result.projected.back(), result.projected[3000]);
  EXPECT_EQ(result.kept.back(), result.kept[3000]);
  EXPECT_EQ(result.neighborhood.k, alone.neighborhood.k);
  EXPECT_EQ(result.summary.lambda, alone.summary.lambda);
  for (size_t i = 0; i < single.size(); ++i) {
    ASSERT_EQ(result.projected[i], alone.projected[i]) << i;
  }
  for (size_t c = 0; c < copied.size(); ++c) {
    const int original = copied[c];
    const Point3 copy = result.projected[single.size() + c];
    const Point3 normal = alone.normals[original];
    const Point3 moved = copy - alone.projected[original];
    ASSERT_LT(std::abs(moved.dot(normal)), 1e-12) << c;  // along the surface
    ASSERT_LT(moved.norm(), 6.0 * jitter) << c;
    ASSERT_EQ(result.kept[single.size() + c], alone.kept[original]) << c;
  }

  // Unmerged, each copy dominates its point's pair weights: lambda collapses.
  DenoiseOptions unmerged = options;
  unmerged.merge_duplicates = false;
  const DenoiseResult raw = DenoisePointSet(twice, unmerged);
  EXPECT_EQ(raw.num_near_repeats, 0);
  EXPECT_LT(raw.summary.lambda, 0.1 * result.summary.lambda);
}

}  // namespace
}  // namespace lpd::solvers
