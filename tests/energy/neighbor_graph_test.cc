// N(i) against brute force, M as the symmetric closure of N, incidence lists.
#include "energy/neighbor_graph.h"

#include <algorithm>
#include <set>

#include <gtest/gtest.h>

#include "test_problems.h"

namespace lpd::energy {
namespace {

TEST(NeighborGraph, MatchesBruteForceNearestNeighbours) {
  const PointList points = testing::NoisySphere(300, 0.05, 7);
  const int k = 9;
  const NeighborGraph graph = BuildNeighborGraph(points, k, 2);
  ASSERT_EQ(graph.num_points(), 300);
  for (int i = 0; i < 300; ++i) {
    std::vector<double> all;
    for (int j = 0; j < 300; ++j) {
      if (j != i) all.push_back((points[i] - points[j]).squaredNorm());
    }
    std::sort(all.begin(), all.end());
    for (int a = 0; a < k; ++a) {
      const int j = graph.NeighborsOf(i)[a];
      EXPECT_NE(j, i);
      EXPECT_DOUBLE_EQ((points[i] - points[j]).squaredNorm(), all[a]);
    }
  }
}

TEST(NeighborGraph, PairsAreTheSymmetricClosureOnce) {
  const PointList points = testing::NoisyPlane(200, 0.01, 3);
  const NeighborGraph graph = BuildNeighborGraph(points, 6, 1);
  std::set<std::pair<int, int>> expected;
  for (int i = 0; i < 200; ++i) {
    for (int a = 0; a < 6; ++a) {
      const int j = graph.NeighborsOf(i)[a];
      expected.insert({std::min(i, j), std::max(i, j)});
    }
  }
  std::set<std::pair<int, int>> got;
  for (const auto& pair : graph.pairs) {
    EXPECT_LT(pair[0], pair[1]);
    EXPECT_TRUE(got.insert({pair[0], pair[1]}).second) << "pair stored twice";
  }
  EXPECT_EQ(got, expected);
  // Every pair is listed exactly once at each of its two points.
  std::vector<int> seen(graph.num_pairs(), 0);
  for (int i = 0; i < 200; ++i) {
    for (int e = graph.incident_offsets[i]; e < graph.incident_offsets[i + 1]; ++e) {
      const auto& pair = graph.pairs[graph.incident_pairs[e]];
      EXPECT_TRUE(pair[0] == i || pair[1] == i);
      ++seen[graph.incident_pairs[e]];
    }
  }
  for (int count : seen) EXPECT_EQ(count, 2);
  // In lexicographic order, each point's pairs in increasing partner order (K's rows rely
  // on it), and the same lists whatever the thread count.
  const NeighborGraph two_threads = BuildNeighborGraph(points, 6, 2);
  for (const NeighborGraph* built : {&graph, &two_threads}) {
    EXPECT_TRUE(std::is_sorted(built->pairs.begin(), built->pairs.end()));
    for (int i = 0; i < 200; ++i) {
      int previous = -1;
      for (int e = built->incident_offsets[i]; e < built->incident_offsets[i + 1]; ++e) {
        const auto& pair = built->pairs[built->incident_pairs[e]];
        const int partner = pair[0] == i ? pair[1] : pair[0];
        EXPECT_GT(partner, previous) << i;
        previous = partner;
      }
    }
  }
  EXPECT_EQ(two_threads.pairs, graph.pairs);
  EXPECT_EQ(two_threads.incident_offsets, graph.incident_offsets);
  EXPECT_EQ(two_threads.incident_pairs, graph.incident_pairs);
}

TEST(NeighborGraph, ThreadsBuildTheSameListsOnALargerCloud) {
  // Large enough that the threads fill the lists at the same time (in unsorted point order,
  // so that every point's pairs come from both threads' rows).
  const PointList points = testing::NoisyPlane(20000, 0.01, 4);
  const NeighborGraph one = BuildNeighborGraph(points, 8, 1);
  const NeighborGraph two = BuildNeighborGraph(points, 8, 2);
  EXPECT_EQ(two.pairs, one.pairs);
  EXPECT_EQ(two.incident_offsets, one.incident_offsets);
  EXPECT_EQ(two.incident_pairs, one.incident_pairs);
}

TEST(NeighborGraph, ExcludesSelfAmongDuplicates) {
  PointList points = testing::NoisyPlane(50, 0.0, 5);
  for (int copy = 0; copy < 6; ++copy) points.push_back(points[0]);  // 7 copies of p_0
  const NeighborGraph graph = BuildNeighborGraph(points, 4, 1);
  for (int i = 0; i < graph.num_points(); ++i) {
    for (int a = 0; a < 4; ++a) EXPECT_NE(graph.NeighborsOf(i)[a], i);
  }
}

TEST(NeighborGraph, RejectsTooFewPoints) {
  const PointList points = testing::NoisyPlane(5, 0.0, 1);
  EXPECT_THROW(BuildNeighborGraph(points, 5, 1), std::invalid_argument);
  EXPECT_NO_THROW(BuildNeighborGraph(points, 4, 1));
}

}  // namespace
}  // namespace lpd::energy
