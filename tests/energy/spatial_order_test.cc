// The Morton order: codes against bit-by-bit interleaving, the order is a permutation that
// puts k-NN neighbours close in memory, and odd inputs do not break it.
#include "energy/spatial_order.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "energy/neighbor_graph.h"
#include "test_problems.h"

namespace lpd::energy {
namespace {

uint64_t InterleaveBitByBit(uint32_t x, uint32_t y, uint32_t z) {
  uint64_t code = 0;
  for (int b = 0; b < 21; ++b) {
    code |= static_cast<uint64_t>((x >> b) & 1u) << (3 * b);
    code |= static_cast<uint64_t>((y >> b) & 1u) << (3 * b + 1);
    code |= static_cast<uint64_t>((z >> b) & 1u) << (3 * b + 2);
  }
  return code;
}

TEST(SpatialOrder, MortonCodeInterleavesBits) {
  EXPECT_EQ(MortonCode(1, 0, 0), 1u);
  EXPECT_EQ(MortonCode(0, 1, 0), 2u);
  EXPECT_EQ(MortonCode(0, 0, 1), 4u);
  EXPECT_EQ(MortonCode(3, 0, 0), 9u);
  std::mt19937 rng(1);
  std::uniform_int_distribution<uint32_t> cell(0, (1u << 21) - 1);
  for (int trial = 0; trial < 1000; ++trial) {
    const uint32_t x = cell(rng), y = cell(rng), z = cell(rng);
    ASSERT_EQ(MortonCode(x, y, z), InterleaveBitByBit(x, y, z)) << x << " " << y << " " << z;
  }
}

// Mean |position of i - position of j| over the k-NN pairs, for points in the given order.
double MeanNeighbourGap(const PointList& points) {
  const NeighborGraph graph = BuildNeighborGraph(points, 10, 2);
  double sum = 0.0;
  for (const auto& pair : graph.pairs) sum += pair[1] - pair[0];
  return sum / graph.num_pairs();
}

TEST(SpatialOrder, PutsNeighboursCloseInMemory) {
  const PointList points = testing::NoisySphere(20000, 0.001, 7);  // random order
  const std::vector<int> order = MortonOrder(points);
  std::vector<int> seen(points.size(), 0);
  PointList ordered;
  for (int index : order) {
    ++seen[index];
    ordered.push_back(points[index]);
  }
  for (size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i], 1) << "point " << i;
  const double before = MeanNeighbourGap(points);
  const double after = MeanNeighbourGap(ordered);
  EXPECT_LT(after, before / 20.0) << before << " -> " << after;
}

TEST(SpatialOrder, OddInputs) {
  EXPECT_TRUE(MortonOrder({}).empty());
  // Identical points keep their order; a non-finite point gets the lowest code.
  const PointList same(5, Point3(1.0, 2.0, 3.0));
  EXPECT_EQ(MortonOrder(same), (std::vector<int>{0, 1, 2, 3, 4}));
  const PointList with_nan = {Point3(1, 1, 1), Point3(0, 0, 0), Point3(NAN, 0, 0)};
  EXPECT_EQ(MortonOrder(with_nan), (std::vector<int>{1, 2, 0}));
}

}  // namespace
}  // namespace lpd::energy
