// lpd: k-nearest-neighbour and within-radius queries against a point list, run in parallel:
// the one k-NN loop that the k-NN graph, the noise probe, the isolation test and the subsample
// extension share, and the radius loop of the layers between which points move.
#ifndef LPD_ENERGY_NEAREST_NEIGHBORS_H_
#define LPD_ENERGY_NEAREST_NEIGHBORS_H_

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "energy/cell_grid.h"
#include "energy/knn_by_radius.h"
#include "energy/point3.h"
#include "energy/point_kd_tree.h"

namespace lpd::energy {

class NearestNeighbors {
 public:
  // From this k on, a query first gathers the points within a radius guessed from the last
  // query's k-th distance and sorts them by bucket (even_key_sort.h): nanoflann's sorted
  // insertion costs O(k) a candidate, the bucket sort O(1) (docs/performance.md, "The
  // neighbours sorted by bucket": 1.2x faster than nanoflann at k = 32, 1.9x at 131, the same
  // at 20).
  static constexpr int kRadiusFirstMinK = 24;

  // Builds a k-d tree over `points`, which must outlive this object.
  explicit NearestNeighbors(const PointList& points)
      : adaptor_{points},
        tree_(3, adaptor_, nanoflann::KDTreeSingleIndexAdaptorParams(kKdTreeLeafSize)) {
    tree_.buildIndex();
  }
  NearestNeighbors(const NearestNeighbors&) = delete;
  NearestNeighbors& operator=(const NearestNeighbors&) = delete;

  // For q in [0, count), on `num_threads` OpenMP threads: finds the k points nearest to
  // query(q) (a Point3, in the frame of the points) and calls
  //   visit(q, nearest, squared_distances, found)
  // with their indices and squared distances, nearest first (equal distances by index from
  // kRadiusFirstMinK on); found = min(k, points). A query that is one of the points finds
  // itself (or a duplicate of it) first. The results do not depend on the thread count.
  template <typename Query, typename Visit>
  void ForEach(int count, int k, int num_threads, const Query& query, const Visit& visit) const {
    const bool radius_first = k >= kRadiusFirstMinK;
    double median_squared = 0.0;  // the median k-th distance, squared
    const std::optional<CellGrid> grid =
        radius_first ? GridForSearch(count, k, query, &median_squared) : std::nullopt;
#pragma omp parallel num_threads(num_threads)
    {
      std::vector<int> nearest(k);
      std::vector<double> squared_distances(k);
      KnnByRadius by_radius;
      // Each thread's first guess: from the median k-th distance, not a miss and nanoflann's
      // search.
      if (grid) by_radius.Guess(median_squared);
#pragma omp for schedule(static)
      for (int q = 0; q < count; ++q) {
        const Point3 p = query(q);
        const int found = radius_first
                              ? by_radius.Search(&tree_, grid ? &*grid : nullptr, p, k,
                                                 nearest.data(), squared_distances.data())
                              : static_cast<int>(tree_.knnSearch(p.data(), k, nearest.data(),
                                                                 squared_distances.data()));
        visit(q, nearest.data(), squared_distances.data(), found);
      }
    }
  }

  // For q in [0, count), on `num_threads` OpenMP threads: finds the points within
  // sqrt(squared_radius(q)) of query(q) and calls visit(q, within) with their indices, in
  // an order that is the same for any thread count but not by distance (by cell of a grid
  // of half the median radius, cell_grid.h, or the tree's traversal where that is 0).
  template <typename Query, typename SquaredRadius, typename Visit>
  void ForEachWithin(int count, int num_threads, const Query& query,
                     const SquaredRadius& squared_radius, const Visit& visit) const {
    const std::optional<CellGrid> grid = GridOfHalfTheMedian(count, squared_radius);
#pragma omp parallel num_threads(num_threads)
    {
      std::vector<std::pair<int, double>> matches;
      std::vector<int> within;
      const nanoflann::SearchParams unsorted(32, 0.0f, false);
#pragma omp for schedule(static)
      for (int q = 0; q < count; ++q) {
        const Point3 p = query(q);
        matches.clear();
        if (grid) {
          grid->Within(p, squared_radius(q), &matches);
        } else {
          tree_.radiusSearch(p.data(), squared_radius(q), matches, unsorted);
        }
        within.resize(matches.size());
        for (size_t m = 0; m < matches.size(); ++m) within[m] = matches[m].first;
        visit(q, within);
      }
    }
  }

 private:
  // A grid of cells half the median length over up to kGridSampleQueries queries spread over
  // [0, count), squared_length(q) each length squared; none where that median is 0 or not
  // finite (then the tree gathers).
  template <typename SquaredLength>
  std::optional<CellGrid> GridOfHalfTheMedian(int count, const SquaredLength& squared_length,
                                              double* median_squared = nullptr) const {
    const int samples = std::min(count, kGridSampleQueries);
    if (samples == 0) return std::nullopt;
    std::vector<double> squared(samples);
    for (int s = 0; s < samples; ++s) {
      squared[s] = squared_length(static_cast<int>(static_cast<int64_t>(s) * count / samples));
    }
    std::nth_element(squared.begin(), squared.begin() + samples / 2, squared.end());
    if (median_squared) *median_squared = squared[samples / 2];
    const double cell_size = 0.5 * std::sqrt(squared[samples / 2]);
    if (!(cell_size > 0.0) || !std::isfinite(cell_size)) return std::nullopt;
    return CellGrid(adaptor_.points, cell_size);
  }

  // For the k-nearest search: cells of half the median distance to the k-th nearest (found by
  // the tree, by radius: nanoflann's sorted insertion costs O(k) a candidate, 30 ms for 32
  // queries of 1,500), so that a guessed radius (kGuessGrowth over a neighbour's) spans
  // about five.
  template <typename Query>
  std::optional<CellGrid> GridForSearch(int count, int k, const Query& query,
                                        double* median_squared) const {
    std::vector<int> nearest(k);
    std::vector<double> squared_distances(k);
    KnnByRadius by_radius;
    return GridOfHalfTheMedian(count, [&](int q) {
      const int found = by_radius.Search(&tree_, nullptr, query(q), k, nearest.data(),
                                         squared_distances.data());
      return found > 0 ? squared_distances[found - 1] : 0.0;
    }, median_squared);
  }

  static constexpr int kGridSampleQueries = 32;

  PointListAdaptor adaptor_;
  L2PointKdTree tree_;
};

}  // namespace lpd::energy

#endif  // LPD_ENERGY_NEAREST_NEIGHBORS_H_
