#include "solvers/offset_feedback.h"

#include <algorithm>
#include <cmath>

#include "energy/nearest_neighbors.h"
#include "solvers/movable_rows.h"

namespace lpd::solvers {

energy::PointList FeedBackMeanOffsets(const energy::PointList& inputs,
                                      const energy::PointList& outputs,
                                      const energy::PointList& normals,
                                      const std::vector<uint8_t>& movable, int num_threads,
                                      size_t max_kept_neighbor_bytes) {
  const std::vector<int> rows = MovableRowsWithNormal(movable, normals);  // those that take part
  energy::PointList result = outputs;
  const int count = static_cast<int>(rows.size());
  if (count < 2) return result;
  energy::PointList points(count);
  std::vector<double> offset(count);
  for (int r = 0; r < count; ++r) {
    const int i = rows[r];
    points[r] = outputs[i];
    offset[r] = normals[i].dot(inputs[i] - outputs[i]);
  }
  const double min_cosine = std::cos(kFeedbackMaxAngleDegrees * M_PI / 180.0);
  const int neighbors = std::min(kFeedbackNeighbors, count);
  const energy::NearestNeighbors search(points);
  // Each point's neighbours, kept for the second pass where they fit, searched again where
  // they do not (docs/performance.md, "The feedback's neighbours kept").
  const size_t kept_size = static_cast<size_t>(count) * neighbors;
  const bool keep = kept_size * sizeof(int) <= max_kept_neighbor_bytes;
  std::vector<int> kept(keep ? kept_size : 0);
  std::vector<int> kept_found(keep ? count : 0);
  // The mean offset m and its squared standard error v of each point; v < 0: no estimate.
  std::vector<double> mean(count, 0.0), squared_error(count, -1.0);
  search.ForEach(count, neighbors, num_threads, [&points](int r) { return points[r]; },
                 [&](int r, const int* nearest, const double*, int found) {
                   if (keep) {
                     std::copy_n(nearest, found, kept.data() + static_cast<size_t>(r) * neighbors);
                     kept_found[r] = found;
                   }
                   const energy::Point3& n = normals[rows[r]];
                   double sum = 0.0, sum_of_squares = 0.0;
                   int used = 0;
                   for (int a = 0; a < found; ++a) {
                     const double cosine = n.dot(normals[rows[nearest[a]]]);
                     if (std::abs(cosine) < min_cosine) continue;
                     const double z = cosine > 0.0 ? offset[nearest[a]] : -offset[nearest[a]];
                     sum += z;
                     sum_of_squares += z * z;
                     ++used;
                   }
                   if (used < 2) return;
                   mean[r] = sum / used;
                   const double variance =
                       std::max(0.0, (sum_of_squares - used * mean[r] * mean[r]) / (used - 1));
                   squared_error[r] = variance / used;
                 });
  // The bias's local spread: E[m^2] = b^2 + v, so max(0, m^2 - v) estimates b^2 at each
  // point, and its mean over the same neighbours is the prior variance tau^2 of the bias.
  // The posterior mean of a bias b ~ N(0, tau^2) seen as m ~ N(b, v) is m tau^2 / (tau^2 + v)
  // (empirical Bayes; docs/method.md, "The mean offset fed back").
  std::vector<double> shift(count, 0.0);
  auto shrink = [&](int r, const int* nearest, const double*, int found) {
    if (squared_error[r] < 0.0) return;
    double sum = 0.0;
    int used = 0;
    for (int a = 0; a < found; ++a) {
      const int j = nearest[a];
      if (squared_error[j] < 0.0) continue;
      sum += std::max(0.0, mean[j] * mean[j] - squared_error[j]);
      ++used;
    }
    const double prior = sum / used;
    if (prior > 0.0) shift[r] = mean[r] * prior / (prior + squared_error[r]);
  };
  if (keep) {
#pragma omp parallel for schedule(static) num_threads(num_threads)
    for (int r = 0; r < count; ++r) {
      shrink(r, kept.data() + static_cast<size_t>(r) * neighbors, nullptr, kept_found[r]);
    }
  } else {
    search.ForEach(count, neighbors, num_threads, [&points](int r) { return points[r]; },
                   shrink);
  }
  for (int r = 0; r < count; ++r) {
    const int i = rows[r];
    result[i] = outputs[i] + shift[r] * normals[i];
  }
  return result;
}

energy::PointList CarryFeedback(const energy::PointList& solved,
                                const energy::PointList& fed_back,
                                const energy::PointList& solved_normals,
                                const std::vector<uint8_t>& solved_movable,
                                const energy::PointList& outputs,
                                const energy::PointList& normals,
                                const std::vector<uint8_t>& movable, int num_threads) {
  std::vector<int> rows;  // the solved points that took part
  for (size_t j = 0; j < solved.size(); ++j) {
    if (solved_movable[j] && solved_normals[j].squaredNorm() > 0.0) {
      rows.push_back(static_cast<int>(j));
    }
  }
  energy::PointList result = outputs;
  if (rows.empty()) return result;
  energy::PointList sources(rows.size());
  for (size_t r = 0; r < rows.size(); ++r) sources[r] = solved[rows[r]];
  const double min_cosine = std::cos(kFeedbackMaxAngleDegrees * M_PI / 180.0);
  const energy::NearestNeighbors search(sources);
  search.ForEach(static_cast<int>(outputs.size()), 1, num_threads,
                 [&outputs](int i) { return outputs[i]; },
                 [&](int i, const int* nearest, const double*, int found) {
                   const energy::Point3& n = normals[i];
                   if (found < 1 || !movable[i] || !(n.squaredNorm() > 0.0)) return;
                   const int j = rows[nearest[0]];
                   if (std::abs(n.dot(solved_normals[j])) < min_cosine) return;
                   result[i] = outputs[i] + n.dot(fed_back[j] - solved[j]) * n;
                 });
  return result;
}

}  // namespace lpd::solvers
