// The bilateral baseline of cgal_baselines.h: normals by PCA or jet fitting, oriented by a
// minimum spanning tree, then CGAL's bilateral smoothing (Huang et al. 2013).
#include <stdexcept>
#include <utility>

#include <CGAL/bilateral_smooth_point_set.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/pca_estimate_normals.h>
#include <CGAL/property_map.h>

#include "experiments/baselines/cgal_baselines.h"
#include "experiments/baselines/cgal_points.h"

namespace lpd::experiments {

std::string ToString(NormalEstimator estimator) {
  return estimator == NormalEstimator::kPca ? "pca" : "jet";
}

NormalEstimator ParseNormalEstimator(const std::string& name) {
  if (name == "pca") return NormalEstimator::kPca;
  if (name == "jet") return NormalEstimator::kJet;
  throw std::invalid_argument("normals: '" + name + "' is not one of pca, jet");
}

energy::PointList BilateralSmooth(const energy::PointList& points,
                                  const BilateralOptions& options) {
  if (options.k < 3 || options.k >= static_cast<int>(points.size())) {
    throw std::invalid_argument("bilateral: k must be in [3, number of points), got " +
                                std::to_string(options.k));
  }
  if (!(options.sharpness_angle_deg > 0.0 && options.sharpness_angle_deg < 90.0)) {
    throw std::invalid_argument("bilateral: sharpness_angle must be in (0, 90) degrees");
  }
  if (options.iterations < 1) throw std::invalid_argument("bilateral: iterations must be >= 1");

  using PointWithNormal = std::pair<cgal::Point, cgal::Vector>;
  std::vector<PointWithNormal> oriented;
  oriented.reserve(points.size());
  for (const energy::Point3& p : points) oriented.emplace_back(cgal::ToCgal(p), cgal::Vector(0, 0, 0));
  const auto parameters = CGAL::parameters::point_map(
                              CGAL::First_of_pair_property_map<PointWithNormal>())
                              .normal_map(CGAL::Second_of_pair_property_map<PointWithNormal>());
  if (options.normals == NormalEstimator::kPca) {
    CGAL::pca_estimate_normals<CGAL::Sequential_tag>(oriented, options.k, parameters);
  } else {
    CGAL::jet_estimate_normals<CGAL::Sequential_tag>(oriented, options.k, parameters);
  }
  // Points the tree cannot reach keep their unoriented normal (CGAL moves them to the end).
  CGAL::mst_orient_normals(oriented, options.k, parameters);
  for (int pass = 0; pass < options.iterations; ++pass) {
    CGAL::bilateral_smooth_point_set<CGAL::Sequential_tag>(
        oriented, options.k, parameters.sharpness_angle(options.sharpness_angle_deg));
  }
  energy::PointList smoothed;
  smoothed.reserve(oriented.size());
  for (const PointWithNormal& p : oriented) smoothed.push_back(cgal::FromCgal(p.first));
  return smoothed;
}

}  // namespace lpd::experiments
