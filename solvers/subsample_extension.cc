#include "solvers/subsample_extension.h"

#include <algorithm>
#include <random>

#include "energy/nearest_neighbors.h"

namespace lpd::solvers {

std::vector<int> ChooseSubsample(int n, int count, uint64_t seed) {
  // Selection sampling (Knuth, TAOCP 3.4.2, Algorithm S): one pass, already in order.
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<int> chosen;
  chosen.reserve(count);
  for (int i = 0; i < n && static_cast<int>(chosen.size()) < count; ++i) {
    const int needed = count - static_cast<int>(chosen.size());
    if ((n - i) * uniform(random) < needed) chosen.push_back(i);
  }
  return chosen;
}

void ExtendToPoints(const energy::Problem& problem, const energy::Variables& v,
                    const std::vector<LocalSurface>& surfaces, double agreement_scale,
                    const PointIndicators& indicators, double mu_l,
                    const FinalDenoisingOptions& options, const energy::PointList& queries,
                    int num_threads,
                    energy::PointList* projected, energy::PointList* normals,
                    PointIndicators* query_indicators) {
  const int count = static_cast<int>(queries.size());
  const int neighbors = problem.k() + 1;
  const PlaneEvidence evidence = ComputePlaneEvidence(problem, v, mu_l, options, num_threads);
  const int blend = std::min(options.blended_surfaces, neighbors);
  const auto project = options.settled_blend ? ProjectOntoSettledBlend : ProjectOntoBlend;
  projected->resize(count);
  normals->resize(count);
  PointIndicators& out = *query_indicators;
  out.outlier_score.resize(count);
  out.feature_score.resize(count);
  out.is_outlier.resize(count);
  out.is_feature.resize(count);
  const energy::NearestNeighbors search(problem.points);
  auto query = [&problem, &queries](int q) { return problem.frame.ToNormalized(queries[q]); };
  auto extend = [&](int q, const int* nearest, const double*, int found) {
    const energy::Point3 p = query(q);
    Eigen::Vector3d on_surface, normal;
    if (project(surfaces, nearest, std::min(blend, found), p, agreement_scale, &on_surface,
                &normal)) {
      (*projected)[q] = problem.frame.ToInput(on_surface);
      (*normals)[q] = normal;
    } else {
      (*projected)[q] = queries[q];
      (*normals)[q].setZero();
    }
    out.outlier_score[q] = OutlierScore(p, nearest, found, v, evidence);
    out.is_outlier[q] = out.outlier_score[q] >= options.outlier_fraction;
    out.feature_score[q] = indicators.feature_score[nearest[0]];
    out.is_feature[q] = indicators.is_feature[nearest[0]];
  };
  search.ForEach(count, neighbors, num_threads, query, extend);
}

}  // namespace lpd::solvers
