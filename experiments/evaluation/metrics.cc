#include "experiments/evaluation/metrics.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "energy/point_kd_tree.h"

namespace lpd::experiments {
namespace {

using energy::Point3;
using energy::PointList;

struct ChamferTerms {
  double squared_l2 = 0.0;  // mean over `from` of the squared L2 distance to `to`
  double l1 = 0.0;          // mean over `from` of the L1 distance to the L1-nearest of `to`
};

// One direction of the symmetric measures: each point of `from` against its nearest in `to`.
ChamferTerms OneSided(const PointList& from, const PointList& to, int num_threads) {
  const energy::PointListAdaptor adaptor{to};
  const nanoflann::KDTreeSingleIndexAdaptorParams params(energy::kKdTreeLeafSize);
  energy::L2PointKdTree l2_tree(3, adaptor, params);
  energy::L1PointKdTree l1_tree(3, adaptor, params);
  l2_tree.buildIndex();
  l1_tree.buildIndex();
  double sum_squared = 0.0, sum_l1 = 0.0;
  const long n = static_cast<long>(from.size());
#pragma omp parallel for schedule(static) num_threads(num_threads) reduction(+ : sum_squared, sum_l1)
  for (long i = 0; i < n; ++i) {
    int index;
    double distance;
    nanoflann::KNNResultSet<double, int> l2(1);
    l2.init(&index, &distance);
    l2_tree.findNeighbors(l2, from[i].data(), nanoflann::SearchParams());
    sum_squared += distance;  // nanoflann's L2 distance is squared
    nanoflann::KNNResultSet<double, int> l1(1);
    l1.init(&index, &distance);
    l1_tree.findNeighbors(l1, from[i].data(), nanoflann::SearchParams());
    sum_l1 += distance;
  }
  return {sum_squared / n, sum_l1 / n};
}

}  // namespace

std::vector<std::pair<std::string, double>> Metrics::Columns() const {
  return {{"mse", mse},
          {"mse_normalized", mse / (diagonal * diagonal)},
          {"mcd", mcd},
          {"mcd_normalized", mcd / diagonal},
          {"snr_db", snr_db},
          {"mean_distance", mean_distance},
          {"mean_distance_normalized", mean_distance / diagonal},
          {"rms_distance", rms_distance},
          {"rms_distance_normalized", rms_distance / diagonal},
          {"max_distance", max_distance},
          {"max_distance_normalized", max_distance / diagonal}};
}

Metrics ComputeMetrics(const PointList& output, const GroundTruth& truth, int num_threads) {
  if (output.empty()) throw std::invalid_argument("cannot score an empty point set");
  if (truth.samples.empty()) throw std::invalid_argument("the ground truth has no samples");
  Metrics metrics;
  metrics.num_points = static_cast<long>(output.size());
  metrics.diagonal = truth.diagonal;
  const ChamferTerms forward = OneSided(output, truth.samples, num_threads);
  const ChamferTerms backward = OneSided(truth.samples, output, num_threads);
  metrics.mse = 0.5 * (forward.squared_l2 + backward.squared_l2);
  metrics.mcd = 0.5 * (forward.l1 + backward.l1);

  Point3 centroid = Point3::Zero();
  for (const Point3& g : truth.samples) centroid += g;
  centroid /= static_cast<double>(truth.samples.size());
  double signal = 0.0;
  for (const Point3& g : truth.samples) signal += (g - centroid).squaredNorm();
  signal /= static_cast<double>(truth.samples.size());
  metrics.snr_db = 10.0 * std::log10(signal / metrics.mse);

  if (truth.surface_distances) {
    metrics.distances = truth.surface_distances(output, num_threads);
    const std::vector<double>& d = metrics.distances;
    double sum = 0.0, sum_squared = 0.0, max = 0.0;
    for (double x : d) {
      sum += x;
      sum_squared += x * x;
      max = std::max(max, x);
    }
    metrics.mean_distance = sum / d.size();
    metrics.rms_distance = std::sqrt(sum_squared / d.size());
    metrics.max_distance = max;
  } else {
    metrics.mean_distance = metrics.rms_distance = metrics.max_distance = NAN;
  }
  return metrics;
}

double DetectionScore::precision() const {
  const long detected = true_positives + false_positives;
  return detected == 0 ? NAN : static_cast<double>(true_positives) / detected;
}

double DetectionScore::recall() const {
  const long actual = true_positives + false_negatives;
  return actual == 0 ? NAN : static_cast<double>(true_positives) / actual;
}

DetectionScore ScoreDetection(const std::vector<uint8_t>& detected,
                              const std::vector<uint8_t>& actual) {
  if (detected.size() != actual.size()) {
    throw std::invalid_argument("detections and labels differ in length");
  }
  DetectionScore score;
  for (size_t i = 0; i < detected.size(); ++i) {
    if (detected[i] && actual[i]) ++score.true_positives;
    if (detected[i] && !actual[i]) ++score.false_positives;
    if (!detected[i] && actual[i]) ++score.false_negatives;
  }
  return score;
}

ThresholdDetection BestDistanceThreshold(const std::vector<double>& distances,
                                         const std::vector<uint8_t>& labels) {
  if (distances.size() != labels.size()) {
    throw std::invalid_argument("distances and labels differ in length");
  }
  const long positives = std::count_if(labels.begin(), labels.end(), [](uint8_t l) { return l; });
  if (positives == 0) throw std::invalid_argument("no labelled point to detect");
  std::vector<size_t> farthest_first(distances.size());
  std::iota(farthest_first.begin(), farthest_first.end(), size_t{0});
  std::sort(farthest_first.begin(), farthest_first.end(),
            [&](size_t a, size_t b) { return distances[a] > distances[b]; });
  ThresholdDetection best;
  double best_score = -1.0;
  long flagged = 0, hits = 0;
  for (size_t rank = 0; rank < farthest_first.size(); ++rank) {
    ++flagged;
    hits += labels[farthest_first[rank]] != 0;
    // Ties flag together: a threshold cannot split equal distances.
    const bool tie_follows = rank + 1 < farthest_first.size() &&
                             distances[farthest_first[rank + 1]] ==
                                 distances[farthest_first[rank]];
    if (tie_follows) continue;
    const double score = std::min(static_cast<double>(hits) / flagged,
                                  static_cast<double>(hits) / positives);
    if (score > best_score) {
      best_score = score;
      best.threshold = distances[farthest_first[rank]];
      best.score.true_positives = hits;
      best.score.false_positives = flagged - hits;
      best.score.false_negatives = positives - hits;
    }
  }
  return best;
}

std::vector<uint8_t> FeatureLabels(const PointList& clean_points, const GroundTruth& truth,
                                   double band) {
  if (!truth.feature_distance) throw std::invalid_argument("the ground truth has no features");
  std::vector<uint8_t> labels(clean_points.size());
  for (size_t i = 0; i < clean_points.size(); ++i) {
    labels[i] = truth.feature_distance(clean_points[i]) <= band;
  }
  return labels;
}

}  // namespace lpd::experiments
