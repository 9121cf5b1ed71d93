#include "solvers/final_denoising.h"

#include <cmath>
#include <sstream>
#include <vector>

#include "energy/geman_mcclure.h"
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

bool FinalDenoisingOptions::IsValid(std::string* error) const {
  std::ostringstream out;
  if (!InUnitInterval(outlier_fraction)) {
    out << "outlier_fraction must be in (0, 1], got " << outlier_fraction;
  } else if (blended_surfaces < 1) {
    out << "blended_surfaces must be at least 1, got " << blended_surfaces;
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

std::vector<double> PlaneSupport(const energy::Variables& v) {
  std::vector<double> support(v.l.rows());
  for (size_t j = 0; j < support.size(); ++j) support[j] = v.l.row(j).mean();
  return support;
}

double OutlierScore(const energy::Point3& p, const int* planes, int count,
                    const energy::Variables& v, const std::vector<double>& support,
                    double mu_l) {
  // Evidence that p lies on the surface: the line process each plane h_j gives it (Eq. 6),
  // weighted by that plane's support.
  const energy::GemanMcClure penalty(mu_l);
  double evidence = 0.0;
  for (int a = 0; a < count; ++a) {
    const int j = planes[a];
    const double residual = v.h.row(j).head<3>().dot(p.transpose()) + v.h(j, 3);
    evidence += support[j] * penalty.OptimalLineProcess(residual * residual);
  }
  return 1.0 - evidence / count;
}

PointIndicators ComputeIndicators(const energy::Problem& problem, const energy::Variables& v,
                                  double mu_l, const FinalDenoisingOptions& options) {
  const int n = problem.num_points();
  const int k = problem.k();
  const auto& graph = problem.graph;
  PointIndicators indicators;
  indicators.outlier_score.resize(n);
  indicators.feature_score.resize(n);
  indicators.is_outlier.resize(n);
  indicators.is_feature.resize(n);
  const std::vector<double> support = PlaneSupport(v);
  std::vector<int> fitting_points(k + 1);
  for (int i = 0; i < n; ++i) {
    for (int a = 0; a <= k; ++a) fitting_points[a] = graph.FittingPoint(i, a);
    indicators.outlier_score[i] =
        OutlierScore(problem.points[i], fitting_points.data(), k + 1, v, support, mu_l);
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
  return indicators;
}

}  // namespace lpd::solvers
