// lpd tests: the squared distance between two points summed as nanoflann's L2_Simple_Adaptor
// sums it (x, y, then z, each difference squared and added), for brute-force checks that
// compare the neighbour searches' distances bit for bit.
#ifndef LPD_TESTS_NANOFLANN_DISTANCE_H_
#define LPD_TESTS_NANOFLANN_DISTANCE_H_

#include "energy/point3.h"

namespace lpd::energy {

inline double NanoflannSquaredDistance(const Point3& a, const Point3& b) {
  double squared = 0.0;
  for (int d = 0; d < 3; ++d) {
    const double difference = a[d] - b[d];
    squared += difference * difference;
  }
  return squared;
}

}  // namespace lpd::energy

#endif  // LPD_TESTS_NANOFLANN_DISTANCE_H_
