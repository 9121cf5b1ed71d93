// lpd metrics OUTPUT --ground_truth=SOURCE [--input=NOISY.ply] [--clean=CLEAN.ply]: error
// metrics of a denoised point set, the learned denoisers' benchmark figures (P2M, and CD
// against the clean samples), and outlier / feature detection scores when the noisy input
// carries labels.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <gflags/gflags.h>

#include "cli/commands.h"
#include "cli/denoise_flags.h"
#include "experiments/evaluation/benchmark_metrics.h"
#include "experiments/evaluation/ground_truth_source.h"
#include "experiments/evaluation/metrics.h"
#include "io/point_cloud_io.h"

DEFINE_string(ground_truth, "",
              "the clean model: a mesh (.off/.obj/.ply with faces), a clean point set, or "
              "shape:NAME[:key=value,...] for a procedural shape");
DEFINE_int32(ground_truth_samples, 200000,
             "samples drawn (seeded) from a mesh or shape ground truth for MSE, MCD and SNR");
DEFINE_string(input, "",
              "the noisy input written by `lpd noise` (.ply with is_outlier and "
              "feature_distance): scores the outlier and feature flags of OUTPUT, matched "
              "through OUTPUT's source_index");
DEFINE_string(clean, "",
              "the clean samples the noisy input was made from (the learned denoisers' "
              "benchmark): prints their Chamfer distance CD to OUTPUT");
DEFINE_double(feature_band, 0.01,
              "a clean point within this fraction of the bounding-box diagonal of a sharp "
              "edge counts as a feature point");

namespace lpd::cli {
namespace {

const std::vector<double>& RequireAttribute(const io::PointCloud& cloud, const std::string& name,
                                            const std::string& path) {
  const io::PointAttribute* attribute = cloud.FindAttribute(name);
  if (!attribute) throw std::runtime_error(path + ": no per-point property '" + name + "'");
  return attribute->values;
}

void PrintDetection(const char* what, const experiments::DetectionScore& score) {
  std::printf("%s detection: precision %.4f  recall %.4f  (true %ld, false %ld, missed %ld)\n",
              what, score.precision(), score.recall(), score.true_positives,
              score.false_positives, score.false_negatives);
}

// Scores OUTPUT's flags against the labels of the noisy input it was denoised from. An input
// point absent from OUTPUT was removed as an outlier.
void ScoreAgainstInput(const io::PointCloud& output, const std::string& output_path,
                       const experiments::GroundTruth& truth) {
  const io::PointCloud input = io::ReadPointCloud(FLAGS_input);
  const std::vector<double>& source = RequireAttribute(output, "source_index", output_path);
  const std::vector<double>& outlier = RequireAttribute(output, "outlier", output_path);
  const std::vector<double>& feature = RequireAttribute(output, "feature", output_path);
  const size_t n = input.points.size();
  std::vector<uint8_t> flagged_outlier(n, 1), flagged_feature(n, 0);
  for (size_t o = 0; o < output.points.size(); ++o) {
    const long i = std::lround(source[o]);
    if (i < 0 || static_cast<size_t>(i) >= n) {
      throw std::runtime_error(output_path + ": source_index " + std::to_string(i) +
                               " is not a point of " + FLAGS_input);
    }
    flagged_outlier[i] = outlier[o] != 0.0;
    flagged_feature[i] = feature[o] != 0.0;
  }
  const std::vector<double>& is_outlier = RequireAttribute(input, "is_outlier", FLAGS_input);
  std::vector<uint8_t> outlier_labels(is_outlier.begin(), is_outlier.end());
  PrintDetection("outlier", experiments::ScoreDetection(flagged_outlier, outlier_labels));
  if (std::count(outlier_labels.begin(), outlier_labels.end(), 1) > 0) {
    const experiments::Metrics noisy = experiments::ComputeMetrics(input.points, truth, FLAGS_threads);
    if (!noisy.distances.empty()) {
      const experiments::ThresholdDetection bound = experiments::BestDistanceThreshold(noisy.distances, outlier_labels);
      std::printf("outlier bound: precision %.4f  recall %.4f  (the best threshold on the exact "
                  "distance to the clean surface, %.4g of the diagonal)\n",
                  bound.score.precision(), bound.score.recall(),
                  bound.threshold / truth.diagonal);
    }
  }
  if (const io::PointAttribute* feature_distance = input.FindAttribute("feature_distance")) {
    const std::vector<double>* distance = &feature_distance->values;
    std::vector<uint8_t> feature_labels(n), detected_inliers(n);
    const double band = FLAGS_feature_band * truth.diagonal;
    for (size_t i = 0; i < n; ++i) {
      // Outliers have no clean position: they are neither features nor scored as such.
      feature_labels[i] = !outlier_labels[i] && (*distance)[i] <= band;
      detected_inliers[i] = !outlier_labels[i] && flagged_feature[i];
    }
    PrintDetection("feature", experiments::ScoreDetection(detected_inliers, feature_labels));
  }
}

}  // namespace

int RunMetricsCommand(const std::vector<std::string>& arguments) {
  if (arguments.size() != 1) throw std::invalid_argument("metrics takes one OUTPUT file");
  if (FLAGS_ground_truth.empty()) {
    throw std::invalid_argument("missing --ground_truth=SOURCE (mesh, points or shape:NAME)");
  }
  if (FLAGS_ground_truth_samples < 1) {
    throw std::invalid_argument("ground_truth_samples must be >= 1");
  }
  const io::PointCloud output = io::ReadPointCloud(arguments[0]);
  const experiments::GroundTruth truth = experiments::LoadGroundTruth(FLAGS_ground_truth, FLAGS_ground_truth_samples);
  const experiments::Metrics metrics = experiments::ComputeMetrics(output.points, truth, FLAGS_threads);
  std::printf("points %ld; ground truth %s; bounding-box diagonal %.6g\n", metrics.num_points,
              truth.description.c_str(), metrics.diagonal);
  std::printf("%-26s %14s %14s\n", "metric", "model frame", "/ diagonal");
  const auto columns = metrics.Columns();
  for (size_t c = 0; c < columns.size(); ++c) {
    const auto& [name, value] = columns[c];
    if (name == "snr_db") {
      std::printf("%-26s %14.4f %14s\n", "snr (dB)", value, "(scale-free)");
    } else if (c + 1 < columns.size() && columns[c + 1].first == name + "_normalized") {
      std::printf("%-26s %14.6e %14.6e\n", name.c_str(), value, columns[c + 1].second);
      ++c;
    }
  }
  const double p2m = experiments::PointToMeshDistanceX1e4(output.points, truth, FLAGS_threads);
  if (std::isfinite(p2m)) {
    std::printf("%-26s %14.4f   (unit-sphere frame of the ground truth)\n", "p2m x 1e4", p2m);
  }
  if (!FLAGS_clean.empty()) {
    const double cd = experiments::ChamferDistanceX1e4(
        output.points, io::ReadPoints(FLAGS_clean), FLAGS_threads);
    std::printf("%-26s %14.4f   (unit-sphere frame of %s)\n", "cd x 1e4", cd,
                FLAGS_clean.c_str());
  }
  if (!FLAGS_input.empty()) ScoreAgainstInput(output, arguments[0], truth);
  return 0;
}

}  // namespace lpd::cli
