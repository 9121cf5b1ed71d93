// lpd: k-nearest-neighbour and within-radius queries against a point list, run in parallel:
// the one k-NN loop that the k-NN graph, the noise probe, the isolation test and the subsample
// extension share, and the radius loop of the layers between which points move.
#ifndef LPD_ENERGY_NEAREST_NEIGHBORS_H_
#define LPD_ENERGY_NEAREST_NEIGHBORS_H_

#include <algorithm>
#include <utility>
#include <vector>

#include "energy/point3.h"
#include "energy/point_kd_tree.h"

namespace lpd::energy {

class NearestNeighbors {
 public:
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
  // with their indices and squared distances, nearest first; found = min(k, points). A
  // query that is one of the points finds itself (or a duplicate of it) first. The results
  // do not depend on the thread count.
  template <typename Query, typename Visit>
  void ForEach(int count, int k, int num_threads, const Query& query, const Visit& visit) const {
#pragma omp parallel num_threads(num_threads)
    {
      std::vector<int> nearest(k);
      std::vector<double> squared_distances(k);
#pragma omp for schedule(static)
      for (int q = 0; q < count; ++q) {
        const Point3 p = query(q);
        const int found = static_cast<int>(
            tree_.knnSearch(p.data(), k, nearest.data(), squared_distances.data()));
        visit(q, nearest.data(), squared_distances.data(), found);
      }
    }
  }

  // For q in [0, count), on `num_threads` OpenMP threads: finds the points within
  // sqrt(squared_radius(q)) of query(q) and calls visit(q, within) with their indices, in
  // the order of the tree's traversal (the same for any thread count), not by distance.
  template <typename Query, typename SquaredRadius, typename Visit>
  void ForEachWithin(int count, int num_threads, const Query& query,
                     const SquaredRadius& squared_radius, const Visit& visit) const {
#pragma omp parallel num_threads(num_threads)
    {
      std::vector<std::pair<int, double>> matches;
      std::vector<int> within;
      const nanoflann::SearchParams unsorted(32, 0.0f, false);
#pragma omp for schedule(static)
      for (int q = 0; q < count; ++q) {
        const Point3 p = query(q);
        matches.clear();
        tree_.radiusSearch(p.data(), squared_radius(q), matches, unsorted);
        within.resize(matches.size());
        for (size_t m = 0; m < matches.size(); ++m) within[m] = matches[m].first;
        visit(q, within);
      }
    }
  }

 private:
  PointListAdaptor adaptor_;
  L2PointKdTree tree_;
};

}  // namespace lpd::energy

#endif  // LPD_ENERGY_NEAREST_NEIGHBORS_H_
