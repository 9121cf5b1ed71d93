// lpd: the CGAL kernel of the baselines and reconstructions, and point conversions.
// Exact predicates keep the Delaunay-based algorithms robust; constructions are doubles.
#ifndef LPD_EXPERIMENTS_BASELINES_CGAL_POINTS_H_
#define LPD_EXPERIMENTS_BASELINES_CGAL_POINTS_H_

#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "energy/point3.h"

namespace lpd::experiments::cgal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;

inline Point ToCgal(const energy::Point3& p) { return Point(p.x(), p.y(), p.z()); }
inline energy::Point3 FromCgal(const Point& p) { return energy::Point3(p.x(), p.y(), p.z()); }

inline std::vector<Point> ToCgal(const energy::PointList& points) {
  std::vector<Point> converted;
  converted.reserve(points.size());
  for (const energy::Point3& p : points) converted.push_back(ToCgal(p));
  return converted;
}

inline energy::PointList FromCgal(const std::vector<Point>& points) {
  energy::PointList converted;
  converted.reserve(points.size());
  for (const Point& p : points) converted.push_back(FromCgal(p));
  return converted;
}

}  // namespace lpd::experiments::cgal

#endif  // LPD_EXPERIMENTS_BASELINES_CGAL_POINTS_H_
