// lpd: error metrics of a denoised point set against its ground truth.
//
// MSE and MCD are the symmetric measures of [ZCN*19] used in the paper's Table 1:
//   MSE = 1/2 (mean over output x of |x - g(x)|_2^2 + mean over ground truth g of |g - x(g)|_2^2)
//   MCD = 1/2 (mean over output x of |x - g(x)|_1   + mean over ground truth g of |g - x(g)|_1)
// with g(x) the nearest ground-truth point to x (and x(g) the nearest output point to g)
// under the same norm (L2 for MSE, L1 for MCD). SNR = 10 log10(mean |g - c|^2 / MSE) in dB,
// with c the ground truth's centroid so that SNR does not depend on where the model sits.
// Every length-based figure is also given divided by the bounding-box diagonal (squared for
// MSE); SNR is scale-free.
#ifndef LPD_EXPERIMENTS_EVALUATION_METRICS_H_
#define LPD_EXPERIMENTS_EVALUATION_METRICS_H_

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "energy/point3.h"
#include "experiments/evaluation/ground_truth.h"

namespace lpd::experiments {

struct Metrics {
  long num_points = 0;
  double diagonal = 0.0;
  double mse = 0.0;
  double mcd = 0.0;
  double snr_db = 0.0;
  // Exact distance from the output points to the clean surface; NaN when not known.
  double mean_distance = 0.0;
  double rms_distance = 0.0;
  double max_distance = 0.0;
  // Each output point's distance to the clean surface; empty when not known.
  std::vector<double> distances;

  // Named values, model frame and normalized: mse, mse_normalized (= mse / diagonal^2), mcd,
  // mcd_normalized, snr_db, mean_distance, mean_distance_normalized, rms_..., max_...
  std::vector<std::pair<std::string, double>> Columns() const;
};

// Throws std::invalid_argument if `output` or the ground truth's samples are empty.
Metrics ComputeMetrics(const energy::PointList& output, const GroundTruth& truth,
                       int num_threads);

// Precision and recall of binary detections (outliers, feature points) against labels.
struct DetectionScore {
  long true_positives = 0;
  long false_positives = 0;
  long false_negatives = 0;
  double precision() const;  // NaN when nothing was detected
  double recall() const;     // NaN when there is nothing to detect
};

// Throws std::invalid_argument if the two vectors differ in length.
DetectionScore ScoreDetection(const std::vector<uint8_t>& detected,
                              const std::vector<uint8_t>& actual);

// The best detector that knows each point's exact distance to the clean surface and flags
// the points beyond a threshold. For outliers uniform in a box and Gaussian inliers, the
// likelihood ratio grows with that distance, so no detector that sees only the positions
// beats this one on both precision and recall (Neyman-Pearson): an upper bound for outlier
// detection on a labelled input. `threshold` is the smallest flagged distance of the
// threshold that maximizes min(precision, recall).
struct ThresholdDetection {
  double threshold = 0.0;
  DetectionScore score;
};

// Throws std::invalid_argument if the two vectors differ in length or have no labelled point.
ThresholdDetection BestDistanceThreshold(const std::vector<double>& distances,
                                         const std::vector<uint8_t>& labels);

// Labels the points within `band` of a sharp feature of the ground truth (which must have
// feature distances).
std::vector<uint8_t> FeatureLabels(const energy::PointList& clean_points,
                                   const GroundTruth& truth, double band);

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_EVALUATION_METRICS_H_
