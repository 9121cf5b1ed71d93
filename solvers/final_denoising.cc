#include "solvers/final_denoising.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "energy/geman_mcclure.h"
#include "solvers/median.h"
#include "solvers/parse_by_name.h"

namespace lpd::solvers {
namespace {

bool InUnitInterval(double x) { return x > 0.0 && x <= 1.0; }

}  // namespace

const char* ProjectionName(Projection projection) {
  return projection == Projection::kPlane ? "plane" : "sphere";
}

bool ParseProjection(const std::string& name, Projection* projection) {
  constexpr Projection kProjections[] = {Projection::kPlane, Projection::kSphere};
  return ParseByName(name, kProjections, ProjectionName, projection);
}

FinalDenoisingOptions FinalDenoisingOptions::ForCloudOf(size_t points) const {
  FinalDenoisingOptions options = *this;
  const double share = std::round(blended_share * static_cast<double>(points));
  if (share > blended_surfaces) {
    options.blended_surfaces = static_cast<int>(std::min(share, 1e9));
  }
  options.blended_share = 0.0;
  return options;
}

bool FinalDenoisingOptions::IsValid(std::string* error) const {
  std::ostringstream out;
  if (!InUnitInterval(outlier_fraction)) {
    out << "outlier_fraction must be in (0, 1], got " << outlier_fraction;
  } else if (!(local_noise_ratio >= 1.0 && local_noise_ratio <= 100.0)) {
    out << "local_noise_ratio must be in [1, 100], got " << local_noise_ratio;
  } else if (even_spacing_rounds < 0 || even_spacing_rounds > 1000) {
    out << "even_spacing must be in [0, 1000], got " << even_spacing_rounds;
  } else if (height_smoothing_pairs < 0 || height_smoothing_pairs > 1000) {
    out << "height_smoothing must be in [0, 1000], got " << height_smoothing_pairs;
  } else if (blended_surfaces < 1) {
    out << "blended_surfaces must be at least 1, got " << blended_surfaces;
  } else if (!(blended_share >= 0.0 && blended_share <= 1.0)) {
    out << "blended_share must be in [0, 1], got " << blended_share;
  } else if (!InUnitInterval(feature_line_threshold)) {
    out << "feature_threshold must be in (0, 1], got " << feature_line_threshold;
  } else if (!(feature_fraction >= 0.0 && feature_fraction < 1.0)) {
    out << "feature_fraction must be in [0, 1), got " << feature_fraction;
  } else if (!InUnitInterval(max_removed_fraction)) {
    out << "max_removed_fraction must be in (0, 1], got " << max_removed_fraction;
  } else if (outlier_passes < 1 || outlier_passes > 10) {
    out << "outlier_passes must be in [1, 10], got " << outlier_passes;
  } else if (!(rerun_removed_fraction >= 0.0 && rerun_removed_fraction <= 1.0)) {
    out << "outlier_rerun_fraction must be in [0, 1], got " << rerun_removed_fraction;
  } else {
    return isolation.IsValid(error) && snapping.IsValid(error);
  }
  *error = out.str();
  return false;
}

namespace {

double PlaneResidual(const energy::Variables& v, int j, const energy::Point3& p) {
  return v.h.row(j).head<3>().dot(p.transpose()) + v.h(j, 3);
}

// A plane's line process is widened only where its region's residual scale is at least
// kMinRegionNoiseRatio times the median region's (below, a region's scale is one noise level
// seen through a median of a few residuals: widening there only keeps the noisiest inliers
// of uniform noise) and its neighbourhood's radius at most kMaxRadiusRatio times the median
// radius (scattered outliers fit planes through each other with a large residual scale, but
// their neighbourhoods are wider). Measurements: docs/method.md, "Outliers".
constexpr double kMinRegionNoiseRatio = 1.5;
constexpr double kMaxRadiusRatio = 2.0;

}  // namespace

PlaneEvidence ComputePlaneEvidence(const energy::Problem& problem, const energy::Variables& v,
                                   double mu_l, const FinalDenoisingOptions& options,
                                   int num_threads) {
  const int n = problem.num_points();
  const int columns = problem.k() + 1;
  const auto& graph = problem.graph;
  PlaneEvidence evidence;
  evidence.mu.assign(n, mu_l);
  evidence.support.resize(n);
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int j = 0; j < n; ++j) evidence.support[j] = v.l.row(j).mean();
  if (options.local_noise_ratio <= 1.0 || n == 0) return evidence;
  // s_j: the robust residual scale of h_j over its own neighbourhood; sigma_j: the median
  // of s over N(j) u {j}, steadier than one median of k + 1 residuals.
  // radius_j: the distance from q_j to its farthest fitting point.
  std::vector<double> scale(n), region_scale(n), radius(n);
#pragma omp parallel num_threads(num_threads)
  {
    std::vector<double> values(columns);
#pragma omp for schedule(static)
    for (int j = 0; j < n; ++j) {
      radius[j] = 0.0;
      for (int a = 0; a < columns; ++a) {
        const energy::Point3& q = problem.points[graph.FittingPoint(j, a)];
        values[a] = std::abs(PlaneResidual(v, j, q));
        radius[j] = std::max(radius[j], (q - problem.points[j]).norm());
      }
      scale[j] = std::max(kMedianAbsToSigma * Median(&values), problem.quantization_noise);
    }
#pragma omp for schedule(static)
    for (int j = 0; j < n; ++j) {
      for (int a = 0; a < columns; ++a) values[a] = scale[graph.FittingPoint(j, a)];
      region_scale[j] = Median(&values);
    }
  }
  std::vector<double> all = region_scale;
  const double typical = Median(&all);
  all = radius;
  const double typical_radius = Median(&all);
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int j = 0; j < n; ++j) {
    const bool surface_density = radius[j] <= kMaxRadiusRatio * typical_radius;
    const double ratio = typical > 0.0 ? region_scale[j] / typical : 0.0;
    const double widening = surface_density && ratio >= kMinRegionNoiseRatio
                                ? std::min(ratio, options.local_noise_ratio)
                                : 1.0;
    if (widening == 1.0) continue;
    evidence.mu[j] = mu_l * widening * widening;
    const energy::GemanMcClure penalty(evidence.mu[j]);
    double explained = 0.0;
    for (int a = 0; a < columns; ++a) {
      const double r = PlaneResidual(v, j, problem.points[graph.FittingPoint(j, a)]);
      explained += penalty.OptimalLineProcess(r * r);
    }
    evidence.support[j] = explained / columns;
  }
  return evidence;
}

double OutlierScore(const energy::Point3& p, const int* planes, int count,
                    const energy::Variables& v, const PlaneEvidence& evidence) {
  // Evidence that p lies on the surface: the line process each plane h_j gives it (Eq. 6),
  // weighted by that plane's support.
  double explained = 0.0;
  for (int a = 0; a < count; ++a) {
    const int j = planes[a];
    const double residual = PlaneResidual(v, j, p);
    explained += evidence.support[j] *
                 energy::GemanMcClure(evidence.mu[j]).OptimalLineProcess(residual * residual);
  }
  return 1.0 - explained / count;
}

PointIndicators ComputeIndicators(const energy::Problem& problem, const energy::Variables& v,
                                  double mu_l, const FinalDenoisingOptions& options,
                                  int num_threads) {
  const int n = problem.num_points();
  const int k = problem.k();
  const auto& graph = problem.graph;
  PointIndicators indicators;
  indicators.outlier_score.resize(n);
  indicators.feature_score.resize(n);
  indicators.is_outlier.resize(n);
  indicators.is_feature.resize(n);
  const PlaneEvidence evidence = ComputePlaneEvidence(problem, v, mu_l, options, num_threads);
#pragma omp parallel num_threads(num_threads)
  {
    std::vector<int> fitting_points(k + 1);
#pragma omp for schedule(static)
    for (int i = 0; i < n; ++i) {
      for (int a = 0; a <= k; ++a) fitting_points[a] = graph.FittingPoint(i, a);
      indicators.outlier_score[i] =
          OutlierScore(problem.points[i], fitting_points.data(), k + 1, v, evidence);
      indicators.is_outlier[i] = indicators.outlier_score[i] >= options.outlier_fraction;

      const int begin = graph.incident_offsets[i];
      const int end = graph.incident_offsets[i + 1];
      int low_m = 0;
      for (int e = begin; e < end; ++e) {
        low_m += v.m[graph.incident_pairs[e]] < options.feature_line_threshold;
      }
      indicators.feature_score[i] = end > begin ? static_cast<double>(low_m) / (end - begin) : 0.0;
      indicators.is_feature[i] = indicators.feature_score[i] > options.feature_fraction;
    }
  }
  return indicators;
}

}  // namespace lpd::solvers
