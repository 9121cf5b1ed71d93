#include "solvers/final_denoising.h"

#include <cmath>
#include <sstream>

#include "energy/geman_mcclure.h"
#include "energy/plane_projection.h"
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
    return snapping.IsValid(error);
  }
  *error = out.str();
  return false;
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
  const energy::GemanMcClure penalty(mu_l);
  // How much of its own neighbourhood each plane h_j explains: the mean of l_ja over a.
  std::vector<double> support(n);
  for (int j = 0; j < n; ++j) support[j] = v.l.row(j).mean();
  // Evidence that q_i lies on the surface: the line process each plane h_j, j in N(i) u {i},
  // gives q_i (Eq. 6), weighted by that plane's support.
  std::vector<double> evidence(n, 0.0);
  for (int i = 0; i < n; ++i) {
    const energy::Point3& p = problem.points[i];
    for (int a = 0; a <= k; ++a) {
      const int j = graph.FittingPoint(i, a);
      const double residual = v.h.row(j).head<3>().dot(p.transpose()) + v.h(j, 3);
      evidence[i] += support[j] * penalty.OptimalLineProcess(residual * residual);
    }
  }
  for (int i = 0; i < n; ++i) {
    indicators.outlier_score[i] = 1.0 - evidence[i] / (k + 1);
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

void ProjectOntoTangentPlanes(const energy::Problem& problem, const energy::Variables& v,
                              energy::PointList* points, energy::PointList* normals) {
  const int n = problem.num_points();
  points->resize(n);
  normals->resize(n);
  for (int i = 0; i < n; ++i) {
    const energy::Point3& p = problem.points[i];
    energy::Point3 projected;
    if (energy::ProjectOntoPlane(p, v.t.row(i).transpose(), &projected)) {
      (*points)[i] = problem.frame.ToInput(projected);
      (*normals)[i] = v.t.row(i).head<3>().transpose().normalized();
    } else {
      (*points)[i] = problem.frame.ToInput(p);
      (*normals)[i].setZero();
    }
  }
}

}  // namespace lpd::solvers
