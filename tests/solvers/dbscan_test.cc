// DBSCAN on planted clusters and on the corner cases of its definition.
#include "solvers/dbscan.h"

#include <random>
#include <set>

#include <gtest/gtest.h>

namespace lpd::solvers {
namespace {

Eigen::MatrixXd EuclideanDistances(const std::vector<Eigen::Vector2d>& points) {
  const int m = static_cast<int>(points.size());
  Eigen::MatrixXd distances(m, m);
  for (int a = 0; a < m; ++a) {
    for (int b = 0; b < m; ++b) distances(a, b) = (points[a] - points[b]).norm();
  }
  return distances;
}

TEST(Dbscan, RecoversPlantedClustersAndLeavesScatteredPointsAsNoise) {
  // Three tight Gaussian blobs 10 apart (sigma 0.1, 30 points each) and 6 lone points far
  // from everything: the blobs are the clusters, the lone points noise.
  std::mt19937_64 random(7);
  std::normal_distribution<double> gaussian(0.0, 0.1);
  const std::vector<Eigen::Vector2d> centers = {{0, 0}, {10, 0}, {0, 10}};
  std::vector<Eigen::Vector2d> points;
  std::vector<int> planted;
  for (int c = 0; c < 3; ++c) {
    for (int i = 0; i < 30; ++i) {
      points.push_back(centers[c] + Eigen::Vector2d(gaussian(random), gaussian(random)));
      planted.push_back(c);
    }
  }
  for (int i = 0; i < 6; ++i) {
    points.push_back(Eigen::Vector2d(-20.0 - 5.0 * i, 30.0 + 7.0 * i));
    planted.push_back(kDbscanNoise);
  }
  const DbscanClusters clusters = Dbscan(EuclideanDistances(points), 0.5, 5);
  ASSERT_EQ(clusters.num_clusters, 3);
  std::vector<int> label_of_blob(3, -2);
  for (size_t a = 0; a < points.size(); ++a) {
    if (planted[a] == kDbscanNoise) {
      EXPECT_EQ(clusters.labels[a], kDbscanNoise) << "lone point " << a;
      continue;
    }
    ASSERT_NE(clusters.labels[a], kDbscanNoise) << "blob point " << a;
    if (label_of_blob[planted[a]] == -2) label_of_blob[planted[a]] = clusters.labels[a];
    EXPECT_EQ(clusters.labels[a], label_of_blob[planted[a]]) << "blob point " << a;
  }
  EXPECT_EQ(std::set<int>(label_of_blob.begin(), label_of_blob.end()).size(), 3u);
  // Clusters are numbered in the order of their first core item.
  EXPECT_EQ(label_of_blob, (std::vector<int>{0, 1, 2}));
}

TEST(Dbscan, ChainsThroughCorePointsAndStopsAtBorderPoints) {
  // Points on a line 1 apart, radius 1.05: with min_points 3 every inner point is core, so
  // the whole line is one cluster, its two ends border points. A gap of 2 splits it.
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < 10; ++i) points.push_back(Eigen::Vector2d(i, 0));
  for (int i = 0; i < 5; ++i) points.push_back(Eigen::Vector2d(11 + i, 0));
  const DbscanClusters clusters = Dbscan(EuclideanDistances(points), 1.05, 3);
  ASSERT_EQ(clusters.num_clusters, 2);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(clusters.labels[i], 0) << i;
  for (int i = 10; i < 15; ++i) EXPECT_EQ(clusters.labels[i], 1) << i;
  // min_points above any neighbourhood's size (3 at most here): nothing is core.
  const DbscanClusters sparse = Dbscan(EuclideanDistances(points), 1.05, 4);
  EXPECT_EQ(sparse.num_clusters, 0);
  for (int label : sparse.labels) EXPECT_EQ(label, kDbscanNoise);
}

TEST(Dbscan, MinPointsOneMakesEveryIsolatedItemItsOwnCluster) {
  const std::vector<Eigen::Vector2d> points = {{0, 0}, {5, 0}, {0, 5}};
  const DbscanClusters clusters = Dbscan(EuclideanDistances(points), 1.0, 1);
  EXPECT_EQ(clusters.num_clusters, 3);
  EXPECT_EQ(clusters.labels, (std::vector<int>{0, 1, 2}));
}

TEST(Dbscan, EmptyInputHasNoClusters) {
  const DbscanClusters clusters = Dbscan(Eigen::MatrixXd(0, 0), 1.0, 2);
  EXPECT_EQ(clusters.num_clusters, 0);
  EXPECT_TRUE(clusters.labels.empty());
}

}  // namespace
}  // namespace lpd::solvers
