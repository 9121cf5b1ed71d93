#include "energy/problem.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "energy/coordinate_quantization.h"

namespace lpd::energy {

bool ProblemOptions::IsValid(std::string* error) const {
  if (k < 1) {
    *error = "k must be >= 1, got " + std::to_string(k);
    return false;
  }
  if (!(min_squared_distance_ratio > 0.0)) {
    *error = "min_squared_distance_ratio must be > 0, got " +
             std::to_string(min_squared_distance_ratio);
    return false;
  }
  return true;
}

double MedianAlpha(const Problem& problem) {
  if (problem.alpha.empty()) return 0.0;
  std::vector<double> alpha = problem.alpha;
  const auto middle = alpha.begin() + alpha.size() / 2;
  std::nth_element(alpha.begin(), middle, alpha.end());
  return *middle;
}

double SpacingFromMedianAlpha(double median_alpha, int k) {
  return std::sqrt(2.0 * M_PI * median_alpha / k);
}

double SampleSpacing(const Problem& problem) {
  if (problem.k() <= 0) return 0.0;
  return SpacingFromMedianAlpha(MedianAlpha(problem), problem.k());
}

void ComputeWeights(double min_squared_distance_ratio, Problem* problem, int num_threads) {
  const int n = problem->num_points();
  const int k = problem->k();
  const PointList& p = problem->points;
  problem->alpha.resize(n);
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int i = 0; i < n; ++i) {
    const int* nbrs = problem->graph.NeighborsOf(i);
    double sum = 0.0;
    for (int a = 0; a < k; ++a) sum += (p[i] - p[nbrs[a]]).squaredNorm();
    problem->alpha[i] = sum / k;
  }
  double alpha_sum = 0.0;  // in index order, the same sum for any thread count
  for (int i = 0; i < n; ++i) alpha_sum += problem->alpha[i];
  const double mean_alpha = alpha_sum / n;
  if (!(mean_alpha > 0.0)) {
    throw std::invalid_argument(
        "every point coincides with its k nearest neighbours: remove duplicate points or "
        "lower k");
  }
  const double floor = min_squared_distance_ratio * mean_alpha;
  for (double& a : problem->alpha) a = std::max(a, floor);

  const auto& pairs = problem->graph.pairs;
  const int num_pairs = problem->graph.num_pairs();
  problem->beta.resize(num_pairs);
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int q = 0; q < num_pairs; ++q) {
    const int i = pairs[q][0];
    const int j = pairs[q][1];
    const double squared_distance = std::max((p[i] - p[j]).squaredNorm(), floor);
    problem->beta[q] = (problem->alpha[i] / k + problem->alpha[j] / k) / squared_distance;
  }
}

Problem BuildProblem(const PointList& input_points, const ProblemOptions& options,
                     int num_threads, const SplitSearch* searched) {
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument(error);
  for (size_t i = 0; i < input_points.size(); ++i) {
    if (!input_points[i].allFinite()) {
      throw std::invalid_argument("point " + std::to_string(i) +
                                  " has a non-finite coordinate (NaN or infinity)");
    }
  }
  if (static_cast<int>(input_points.size()) < options.k + 1) {
    throw std::invalid_argument("need at least k+1 = " + std::to_string(options.k + 1) +
                                " points for k = " + std::to_string(options.k) + ", got " +
                                std::to_string(input_points.size()));
  }
  Problem problem;
  problem.frame = ComputeNormalizingFrame(input_points);
  problem.quantization_noise = QuantizationNoise(input_points) / problem.frame.scale;
  problem.points.reserve(input_points.size());
  for (const Point3& x : input_points) problem.points.push_back(problem.frame.ToNormalized(x));
  problem.graph = BuildNeighborGraph(problem.points, options.k, num_threads,
                                     options.split_sheets, searched,
                                     options.thin_region_growth, options.split_neighborhood);
  ComputeWeights(options.min_squared_distance_ratio, &problem, num_threads);
  return problem;
}

}  // namespace lpd::energy
