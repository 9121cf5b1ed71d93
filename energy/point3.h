// lpd: points and point lists, in double precision, as every layer passes them.
#ifndef LPD_ENERGY_POINT3_H_
#define LPD_ENERGY_POINT3_H_

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products of Point3

namespace lpd::energy {

using Point3 = Eigen::Vector3d;
using PointList = std::vector<Point3>;

}  // namespace lpd::energy

#endif  // LPD_ENERGY_POINT3_H_
