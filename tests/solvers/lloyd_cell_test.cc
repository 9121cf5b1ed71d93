#include "solvers/lloyd_cell.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace lpd::solvers {
namespace {

TEST(ClippedCellCentroid, FourNeighboursAcrossTheAxesGiveTheRectangleBetweenTheirBisectors) {
  // Sites (a, 0), (-b, 0), (0, c), (0, -d): the cell is [-b/2, a/2] x [-d/2, c/2], whose
  // corners lie on the sites' hull; any margin keeps all of it.
  const double a = 1.0, b = 0.6, c = 0.8, d = 1.3;
  const Eigen::Vector2d sites[] = {{a, 0.0}, {-b, 0.0}, {0.0, c}, {0.0, -d}};
  Eigen::Vector2d centroid;
  ASSERT_TRUE(ClippedCellCentroid(sites, 4, 0.05, &centroid));
  EXPECT_NEAR(centroid.x(), (a - b) / 4, 1e-12);
  EXPECT_NEAR(centroid.y(), (c - d) / 4, 1e-12);
}

TEST(ClippedCellCentroid, AtARimTheCellEndsAMarginBeyondThePoint) {
  // Sites (a, 0), (-a, 0), (0, -a): the point is on the hull's top edge, so the cell is
  // [-a/2, a/2] x [-a/2, m] and its centroid (0, (m - a/2) / 2): it stays for m = a/2.
  const double a = 1.0;
  const Eigen::Vector2d sites[] = {{a, 0.0}, {-a, 0.0}, {0.0, -a}};
  for (double margin : {0.0, 0.2, 0.5, 0.7}) {
    Eigen::Vector2d centroid;
    ASSERT_TRUE(ClippedCellCentroid(sites, 3, margin, &centroid));
    EXPECT_NEAR(centroid.x(), 0.0, 1e-12) << margin;
    EXPECT_NEAR(centroid.y(), (margin - 0.5 * a) / 2, 1e-12) << margin;
  }
}

TEST(ClippedCellCentroid, HasNoCellWithoutSites) {
  Eigen::Vector2d centroid;
  EXPECT_FALSE(ClippedCellCentroid(nullptr, 0, 0.1, &centroid));
  const Eigen::Vector2d coincident[] = {{0.0, 0.0}};
  EXPECT_FALSE(ClippedCellCentroid(coincident, 1, 0.1, &centroid));
}

// The edges of the hull of `points` found by brute force (a pair with every other point on its
// left or on its line), each as a point on it and its outer unit normal.
std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> HullEdges(
    const std::vector<Eigen::Vector2d>& points) {
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> edges;
  for (size_t i = 0; i < points.size(); ++i) {
    for (size_t j = 0; j < points.size(); ++j) {
      const Eigen::Vector2d edge = points[j] - points[i];
      if (i == j || edge.norm() == 0.0) continue;
      bool hull_edge = true;
      for (size_t k = 0; k < points.size() && hull_edge; ++k) {
        const Eigen::Vector2d to = points[k] - points[i];
        hull_edge = edge.x() * to.y() - edge.y() * to.x() >= -1e-12;
      }
      if (hull_edge) {
        edges.emplace_back(points[i], Eigen::Vector2d(edge.y(), -edge.x()).normalized());
      }
    }
  }
  return edges;
}

TEST(ClippedCellCentroid, MatchesTheCentroidOfAFineGridOfTheCellsPoints) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 12; ++trial) {
    // 3-10 sites in the unit disk, some trials on one side only (a rim).
    const int count = 3 + trial % 8;
    std::vector<Eigen::Vector2d> sites;
    while (static_cast<int>(sites.size()) < count) {
      Eigen::Vector2d s(unit(random), unit(random));
      if (trial % 3 == 0) s.y() = -std::abs(s.y());
      if (s.norm() <= 1.0 && s.norm() > 0.05) sites.push_back(s);
    }
    const double margin = 0.1 + 0.05 * (trial % 4);
    Eigen::Vector2d centroid;
    ASSERT_TRUE(ClippedCellCentroid(sites.data(), count, margin, &centroid));
    std::vector<Eigen::Vector2d> hull_points = sites;
    hull_points.emplace_back(0.0, 0.0);
    const auto edges = HullEdges(hull_points);
    const int steps = 700;
    const double half = 1.0 + margin, cell = 2.0 * half / steps;
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    int inside = 0;
    for (int i = 0; i < steps; ++i) {
      for (int j = 0; j < steps; ++j) {
        const Eigen::Vector2d x(-half + (i + 0.5) * cell, -half + (j + 0.5) * cell);
        bool in_cell = true;
        for (const Eigen::Vector2d& s : sites) in_cell = in_cell && x.norm() <= (x - s).norm();
        for (const auto& [on, outward] : edges) in_cell = in_cell && outward.dot(x - on) <= margin;
        if (in_cell) {
          sum += x;
          ++inside;
        }
      }
    }
    ASSERT_GT(inside, 100) << trial;
    EXPECT_NEAR(centroid.x(), sum.x() / inside, 3e-3) << trial;
    EXPECT_NEAR(centroid.y(), sum.y() / inside, 3e-3) << trial;
  }
}

}  // namespace
}  // namespace lpd::solvers
