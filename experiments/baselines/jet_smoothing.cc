// The jet-smoothing baseline of cgal_baselines.h (CGAL, Cazals and Pouget 2005).
#include <stdexcept>

#include <CGAL/jet_smooth_point_set.h>

#include "experiments/baselines/cgal_baselines.h"
#include "experiments/baselines/cgal_points.h"

namespace lpd::experiments {

energy::PointList JetSmooth(const energy::PointList& points, const JetOptions& options) {
  // A degree-2 jet has 6 coefficients; CGAL needs more neighbours than that to fit it.
  if (options.k < 6 || options.k >= static_cast<int>(points.size())) {
    throw std::invalid_argument("jet: k must be in [6, number of points), got " +
                                std::to_string(options.k));
  }
  if (options.iterations < 1) throw std::invalid_argument("jet: iterations must be >= 1");
  std::vector<cgal::Point> smoothed = cgal::ToCgal(points);
  for (int pass = 0; pass < options.iterations; ++pass) {
    CGAL::jet_smooth_point_set<CGAL::Sequential_tag>(smoothed, options.k);
  }
  return cgal::FromCgal(smoothed);
}

}  // namespace lpd::experiments
