// lpd: one thread's k-nearest search by radius, query after query.
//
// The k nearest lie within any radius that holds k points, so a search gathers the points
// within a guessed radius (from a cell grid, cell_grid.h, or nanoflann's tree) and sorts them
// (even_key_sort.h); the guess for the next query grows from this one's k-th distance, since
// the queries come in an order where neighbours follow each other (Morton order, or the same
// point a round later). A guess that holds fewer than k points falls back to nanoflann's
// k-nearest search where a tree is given, else grows on the grid. Exact either way: the k
// nearest by (distance, index), the same for any guess (docs/performance.md, "The neighbours
// sorted by bucket", "The neighbours gathered by cells").
#ifndef LPD_ENERGY_KNN_BY_RADIUS_H_
#define LPD_ENERGY_KNN_BY_RADIUS_H_

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "energy/cell_grid.h"
#include "energy/even_key_sort.h"
#include "energy/point3.h"
#include "energy/point_kd_tree.h"

namespace lpd::energy {

class KnnByRadius {
 public:
  // Writes the min(k, points) points nearest to p, nearest first (equal distances by index),
  // to nearest and squared_distances, and returns how many. The points are those of `tree`
  // or `grid`, at least one given; with both, the grid gathers and the tree's search answers
  // a guess that misses (the same points with the same squared distances, cell_grid.h).
  int Search(const L2PointKdTree* tree, const CellGrid* grid, const Point3& p, int k,
             int* nearest, double* squared_distances) {
    tree_ = tree;
    grid_ = grid;
    matches_.clear();
    if (squared_radius_ > 0.0) Within(p, squared_radius_);
    if (static_cast<int>(matches_.size()) < k) {
      if (tree) {
        // The guess holds fewer than k: nanoflann's search gives the k-th distance, and the
        // points within it, ties included, are gathered again (all of them if fewer than k).
        const int found =
            static_cast<int>(tree->knnSearch(p.data(), k, nearest, squared_distances));
        matches_.clear();
        if (found < k) {
          for (int a = 0; a < found; ++a) matches_.emplace_back(nearest[a], squared_distances[a]);
        } else {
          Within(p, std::nextafter(squared_distances[k - 1], HUGE_VAL));
        }
      } else {
        // Wider and wider on the grid, until k points or all of them are within.
        const size_t wanted = std::min<size_t>(k, grid->size());
        double squared_radius = std::max(squared_radius_, grid->cell_size() * grid->cell_size());
        while (matches_.size() < wanted && std::isfinite(squared_radius)) {
          squared_radius *= 4.0;
          matches_.clear();
          Within(p, squared_radius);
        }
      }
    }
    // The k nearest by (distance, index), whichever search found them: the same order for
    // any guess, so for any thread count. Sorting all the gathered points (about 1.4 k)
    // costs less than selecting the k nearest first.
    const int found = std::min(k, static_cast<int>(matches_.size()));
    if (found == 0) return 0;
    auto closer = [](const std::pair<int, double>& a, const std::pair<int, double>& b) {
      return a.second < b.second || (a.second == b.second && a.first < b.first);
    };
    SortByEvenKeys(matches_.data(), matches_.size(),
                   [](const std::pair<int, double>& m) { return m.second; }, closer);
    for (int a = 0; a < found; ++a) {
      nearest[a] = matches_[a].first;
      squared_distances[a] = matches_[a].second;
    }
    if (found == k) {
      // After a far query (an outlier) the guess grows at most kMaxGuessRise-fold, not to
      // a radius that would hold much of the cloud.
      const double next = kGuessGrowth * squared_distances[k - 1];
      squared_radius_ =
          squared_radius_ > 0.0 ? std::min(next, kMaxGuessRise * squared_radius_) : next;
    }
    return found;
  }

  // The next search's guessed squared radius: `squared_radius` grown by kGuessGrowth.
  void Guess(double squared_radius) { squared_radius_ = kGuessGrowth * squared_radius; }

 private:
  // The points at squared distances under `squared_radius` from p, in matches_.
  void Within(const Point3& p, double squared_radius) {
    if (grid_) {
      grid_->Within(p, squared_radius, &matches_);
    } else {
      tree_->radiusSearch(p.data(), squared_radius, matches_,
                          nanoflann::SearchParams(32, 0.0f, false));
    }
  }

  // The next guess, in squared distance, over this query's k-th: neighbouring queries
  // (Morton order) differ by a few percent; 1.4 misses on 0.3-3% of them.
  static constexpr double kGuessGrowth = 1.4;
  static constexpr double kMaxGuessRise = 4.0;
  double squared_radius_ = 0.0;
  std::vector<std::pair<int, double>> matches_;
  const L2PointKdTree* tree_ = nullptr;
  const CellGrid* grid_ = nullptr;
};

}  // namespace lpd::energy

#endif  // LPD_ENERGY_KNN_BY_RADIUS_H_
