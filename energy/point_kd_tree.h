// lpd: a nanoflann k-d tree over a PointList, under the Euclidean (L2) or city-block (L1)
// metric. nanoflann reports squared distances for L2 and plain distances for L1.
#ifndef LPD_ENERGY_POINT_KD_TREE_H_
#define LPD_ENERGY_POINT_KD_TREE_H_

#include <nanoflann.hpp>

#include "energy/point3.h"

namespace lpd::energy {

// nanoflann dataset adaptor over a PointList (which must outlive the tree).
struct PointListAdaptor {
  const PointList& points;
  size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(size_t index, size_t dim) const { return points[index][dim]; }
  template <class BoundingBox>
  bool kdtree_get_bbox(BoundingBox&) const { return false; }
};

template <class Metric>
using PointKdTree = nanoflann::KDTreeSingleIndexAdaptor<Metric, PointListAdaptor, 3, int>;
using L2PointKdTree = PointKdTree<nanoflann::L2_Simple_Adaptor<double, PointListAdaptor>>;
using L1PointKdTree = PointKdTree<nanoflann::L1_Adaptor<double, PointListAdaptor>>;

constexpr int kKdTreeLeafSize = 16;

}  // namespace lpd::energy

#endif  // LPD_ENERGY_POINT_KD_TREE_H_
