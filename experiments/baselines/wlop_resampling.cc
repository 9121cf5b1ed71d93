// The WLOP baseline of cgal_baselines.h (CGAL, Huang et al. 2009).
#include <iterator>
#include <stdexcept>

#include <CGAL/compute_average_spacing.h>
#include <CGAL/wlop_simplify_and_regularize_point_set.h>

#include "experiments/baselines/cgal_baselines.h"
#include "experiments/baselines/cgal_points.h"

namespace lpd::experiments {
namespace {

constexpr int kSpacingNeighbours = 6;  // CGAL's usual k for the average spacing

}  // namespace

energy::PointList WlopResample(const energy::PointList& points, const WlopOptions& options) {
  if (!(options.select_percentage > 0.0 && options.select_percentage <= 100.0)) {
    throw std::invalid_argument("wlop: select_percentage must be in (0, 100]");
  }
  if (!(options.radius_spacings > 0.0)) {
    throw std::invalid_argument("wlop: radius_spacings must be > 0");
  }
  if (options.iterations < 1) throw std::invalid_argument("wlop: iterations must be >= 1");
  if (static_cast<int>(points.size()) <= kSpacingNeighbours) {
    throw std::invalid_argument("wlop: needs more than " + std::to_string(kSpacingNeighbours) +
                                " points");
  }
  std::vector<cgal::Point> input = cgal::ToCgal(points);  // WLOP reorders its input
  const double spacing =
      CGAL::compute_average_spacing<CGAL::Sequential_tag>(input, kSpacingNeighbours);
  std::vector<cgal::Point> output;
  CGAL::wlop_simplify_and_regularize_point_set<CGAL::Sequential_tag>(
      input, std::back_inserter(output),
      CGAL::parameters::select_percentage(options.select_percentage)
          .neighbor_radius(options.radius_spacings * spacing)
          .number_of_iterations(options.iterations));
  if (output.empty()) throw std::runtime_error("wlop: no points were selected");
  return cgal::FromCgal(output);
}

}  // namespace lpd::experiments
