#include "solvers/adaptive_heights.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include <Eigen/Dense>

#include "energy/nearest_neighbors.h"
#include "solvers/median.h"
#include "solvers/movable_rows.h"

namespace lpd::solvers {
namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

constexpr int kNumScales = static_cast<int>(kAdaptiveScales.size());

// The sums over the neighbours kept so far of x^a y^b (a + b <= 4) and of z x^a y^b (a + b
// <= 2), from which the normal equations of the height field z = a + (x, y, x^2, xy, y^2)
// are built at each scale.
struct HeightMoments {
  // x^a y^b at index kIndex[a][b].
  static constexpr int kIndex[5][5] = {{0, 1, 2, 3, 4},
                                        {5, 6, 7, 8, -1},
                                        {9, 10, 11, -1, -1},
                                        {12, 13, -1, -1, -1},
                                        {14, -1, -1, -1, -1}};
  double xy[15] = {};
  Vector6 z_rows = Vector6::Zero();
  double z_squares = 0.0;

  void Add(double x, double y, double z) {
    const double xs[5] = {1.0, x, x * x, x * x * x, x * x * x * x};
    const double ys[5] = {1.0, y, y * y, y * y * y, y * y * y * y};
    for (int a = 0; a <= 4; ++a) {
      for (int b = 0; a + b <= 4; ++b) xy[kIndex[a][b]] += xs[a] * ys[b];
    }
    z_rows += z * Vector6(1.0, x, y, xs[2], x * y, ys[2]);
    z_squares += z * z;
  }

  // The intercept of the least-squares field, its leverage (A^-1)_00 and the residual sum of
  // squares; false where the neighbours do not determine the field (too few distinct, or on a
  // line).
  bool Solve(double* intercept, double* leverage, double* residual_squares) const {
    // The powers (a, b) of the field's six terms 1, x, y, x^2, xy, y^2.
    static constexpr int kPowers[6][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};
    Matrix6 normal;
    for (int p = 0; p < 6; ++p) {
      for (int q = 0; q < 6; ++q) {
        normal(p, q) = xy[kIndex[kPowers[p][0] + kPowers[q][0]][kPowers[p][1] + kPowers[q][1]]];
      }
    }
    const Eigen::LDLT<Matrix6> factor(normal);
    const Vector6 diagonal = factor.vectorD();
    if (factor.info() != Eigen::Success ||
        !(diagonal.minCoeff() > 1e-12 * diagonal.maxCoeff())) {
      return false;
    }
    const Vector6 beta = factor.solve(z_rows);
    *intercept = beta[0];
    *leverage = factor.solve(Vector6::Unit(0))[0];
    *residual_squares = std::max(0.0, z_squares - beta.dot(z_rows));
    return true;
  }
};

}  // namespace

energy::PointList RefitHeightsAtAdaptiveScale(const energy::PointList& outputs,
                                              const energy::PointList& normals,
                                              const std::vector<uint8_t>& movable,
                                              int num_threads) {
  const std::vector<int> rows = MovableRowsWithNormal(movable, normals);  // those that take part
  energy::PointList result = outputs;
  const int count = static_cast<int>(rows.size());
  if (count <= kAdaptiveScales[0]) return result;
  energy::PointList current(count), unit_normals(count);
  for (int r = 0; r < count; ++r) {
    current[r] = outputs[rows[r]];
    unit_normals[r] = normals[rows[r]].normalized();
  }
  const double min_cosine = std::cos(kAdaptiveMaxAngleDegrees * M_PI / 180.0);
  const energy::NearestNeighbors search(current);
  const auto query = [&current](int r) { return current[r]; };

  // r: the jitter's deviation, from each output's kJitterNeighbors nearest within the angle.
  std::vector<double> jitter(count, std::numeric_limits<double>::quiet_NaN());
  search.ForEach(count, std::min(2 * kJitterNeighbors + 1, count), num_threads, query,
                 [&](int r, const int* nearest, const double*, int found) {
                   const energy::Point3& n = unit_normals[r];
                   std::vector<double> heights;
                   for (int a = 0; a < found && heights.size() < kJitterNeighbors; ++a) {
                     const int j = nearest[a];
                     if (j == r || std::abs(n.dot(unit_normals[j])) < min_cosine) continue;
                     heights.push_back(std::abs(n.dot(current[j] - current[r])));
                   }
                   if (!heights.empty()) jitter[r] = Median(&heights);
                 });
  std::vector<double> jitters;
  for (double value : jitter) {
    if (!std::isnan(value)) jitters.push_back(value);
  }
  if (jitters.empty()) return result;
  const double band = kJitterBandDeviations * kMedianAbsToSigma * Median(&jitters);

  // Every output's estimates a_m and leverages L_m, for its first `scales[r]` scales, and its
  // first scale's residual variance.
  std::vector<float> intercepts(static_cast<size_t>(count) * kNumScales);
  std::vector<float> leverages(static_cast<size_t>(count) * kNumScales);
  std::vector<int> scales(count, 0);
  std::vector<double> first_variance(count, std::numeric_limits<double>::quiet_NaN());
  const auto fit = [&](int r, const int* nearest, const double* squared_distances, int found) {
    const energy::Point3& n = unit_normals[r];
    const energy::Point3 u = n.unitOrthogonal();
    const energy::Point3 v = n.cross(u);
    // Tangential coordinates in units of the farthest neighbour's distance (only the
    // conditioning depends on it).
    const double unit = std::sqrt(squared_distances[found - 1]);
    if (!(unit > 0.0)) return;
    HeightMoments moments;
    int kept = 0, scale = 0;
    for (int a = 0; a < found && scale < kNumScales; ++a) {
      const int j = nearest[a];
      if (std::abs(n.dot(unit_normals[j])) < min_cosine) continue;
      const energy::Point3 offset = current[j] - current[r];
      const double z = n.dot(offset);
      const double x = u.dot(offset) / unit, y = v.dot(offset) / unit;
      if (!(std::abs(z) <= band + kBandSlope * unit * std::sqrt(x * x + y * y))) continue;
      moments.Add(x, y, z);
      if (++kept < kAdaptiveScales[scale]) continue;
      double intercept, leverage, residual_squares;
      if (!moments.Solve(&intercept, &leverage, &residual_squares)) break;
      const size_t slot = static_cast<size_t>(r) * kNumScales + scale;
      intercepts[slot] = static_cast<float>(intercept);
      leverages[slot] = static_cast<float>(leverage);
      if (scale == 0) first_variance[r] = residual_squares / (kept - 6);
      ++scale;
    }
    scales[r] = scale;
  };
  search.ForEach(count, std::min(kAdaptiveSearched, count), num_threads, query, fit);
  std::vector<double> variances;
  for (double value : first_variance) {
    if (!std::isnan(value)) variances.push_back(value);
  }
  if (variances.empty()) return result;
  const double jitter_variance = Median(&variances);  // g

  // The intersection of the intervals, scale by scale.
#pragma omp parallel for schedule(static) num_threads(num_threads)
  for (int r = 0; r < count; ++r) {
    double low = -std::numeric_limits<double>::infinity();
    double high = std::numeric_limits<double>::infinity();
    double chosen = 0.0;
    for (int scale = 0; scale < scales[r]; ++scale) {
      const size_t slot = static_cast<size_t>(r) * kNumScales + scale;
      const double half_width =
          kIntervalHalfWidth * std::sqrt(jitter_variance * leverages[slot]);
      low = std::max(low, intercepts[slot] - half_width);
      high = std::min(high, intercepts[slot] + half_width);
      if (low > high) break;
      chosen = intercepts[slot];
    }
    result[rows[r]] = current[r] + chosen * unit_normals[r];
  }
  return result;
}

}  // namespace lpd::solvers
