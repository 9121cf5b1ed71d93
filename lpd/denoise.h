// lpd: robust denoising of point sets of piecewise-smooth surfaces through line processes
// (Wei, Chen, Rohmer, Memari, Desbrun; Eurographics 2023). The public C++ API.
//
//   #include <lpd/denoise.h>
//   lpd::Options options;                 // every weight derived from the data
//   options.Set("max_iters", 60);         // any parameter of `lpd denoise --help`, by name
//   const lpd::Result result = lpd::Denoise(points, options);
//   // result.points[r] is input point result.source_index[r], denoised
//
// CMake: find_package(lpd) and target_link_libraries(app PRIVATE lpd::lpd).
#ifndef LPD_DENOISE_H_
#define LPD_DENOISE_H_

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace lpd {

using PointList = std::vector<Eigen::Vector3d>;

// The options of a run, as named parameters: the names, values and defaults of
// `lpd denoise`'s flags and of the Python module's keywords, one declaration each
// (lpd/parameters.h). A parameter not set keeps the preset's value; k, eta, lambda and
// mu_l default to "auto", derived from the data (noise estimate, point spacing).
class Options {
 public:
  // "default" (weights from the data, run to convergence) or "paper" (Table 2 literally).
  // Throws std::invalid_argument for another name.
  explicit Options(const std::string& preset = "default");

  // Sets parameter `name`; throws std::invalid_argument naming the parameter if it is
  // unknown or the value is not valid for it (the CLI's messages).
  Options& Set(const std::string& name, const std::string& value);
  Options& Set(const std::string& name, const char* value);
  Options& Set(const std::string& name, double value);
  Options& Set(const std::string& name, int value);
  Options& Set(const std::string& name, bool value);
  // The value as text ("auto" while a weight follows its data rule).
  std::string Get(const std::string& name) const;

  const std::string& preset() const { return preset_; }
  // The parameters given with Set, in order, as (name, value text).
  const std::vector<std::pair<std::string, std::string>>& given() const { return given_; }

  // "alternating" (Alg. 1, the paper's method) or "ceres" (the joint solve).
  std::string solver = "alternating";
  // Worker threads; 0: all cores. Results are bit-identical at the same thread count.
  int num_threads = 0;

 private:
  std::string preset_;
  std::vector<std::pair<std::string, std::string>> given_;
};

// One iteration of the minimization, as the progress callback sees it.
struct Progress {
  int pass = 1;             // denoising pass (a second one runs without the outliers)
  int iteration = 0;        // from 1, within the pass
  double energy = 0.0;      // Eq. (5) at the end of the iteration
  double point_motion = 0;  // RMS motion of the output points, of the diagonal (NaN at first)
};
// Returning false stops the run after this iteration; Denoise then returns what it has,
// with Summary::stopped set.
using ProgressCallback = std::function<bool(const Progress&)>;

struct Summary {
  std::string version;        // of lpd
  std::string termination;    // CONVERGENCE, NO_CONVERGENCE or USER_ABORT (of the last pass)
  std::string message;        // why the last pass stopped
  bool stopped = false;       // the progress callback stopped the run
  int iterations = 0;         // of the last pass
  int passes = 1;
  int k = 0;
  double noise_sigma = 0.0;   // estimated, of the bounding-box diagonal (0 with k given)
  // The probe's reading that k was chosen from, likewise: below noise_sigma where the noise
  // is as wide as the spacing (the probe under-reads it there), and on the merged sides of a
  // thin part their spread (the sides' gap and noise together).
  double read_sigma = 0.0;
  double spacing = 0.0;       // estimated point spacing, likewise
  double eta = 0.0, lambda = 0.0, mu_l = 0.0, mu_m = 0.0;  // used by the last pass
  int64_t input_points = 0;
  int64_t output_points = 0;
  int64_t outliers = 0;       // flagged, of the input points
  int64_t isolated = 0;       // of those, found by the isolation test
  int64_t far = 0;            // of those, far from the whole cloud (stray points)
  int64_t duplicates = 0;     // input points that repeat an earlier one (solved as it)
  int64_t near_repeats = 0;   // points within a tenth of a spacing of an earlier one (same)
  int64_t separated = 0;      // output points moved to their side of a merged thin part
  int64_t removed = 0;        // not in the output
  int64_t features = 0;       // of the input points
  int64_t solved_points = 0;  // in the last pass's problem (less when subsampled)
  std::string note;           // e.g. why flagged outliers were kept
  double seconds = 0.0;
  double setup_seconds = 0.0;  // normalization and k-NN graph
  // The wall seconds of each stage that ran ("order and probe", "graph", "solve",
  // "projection", "even spacing", ...), in the order each first ran, summed over the passes.
  std::vector<std::pair<std::string, double>> stage_seconds;
};

// One entry per output point: the input points that were not removed as outliers, in
// input order, denoised.
struct Result {
  PointList points;
  PointList normals;                   // unit normal of the fitted plane (zero if undefined)
  std::vector<int64_t> source_index;   // the input point each output point comes from
  std::vector<float> outlier_score;    // 0 (inlier) .. 1
  std::vector<float> feature_score;    // share of neighbours across a sharp feature
  std::vector<uint8_t> is_outlier;     // flagged (kept only when removal was off or refused)
  std::vector<uint8_t> is_feature;
  Summary summary;
};

// Denoises `points` (finite, at least a few more than k). `normals`, one per point, are read
// only with parameter initialization = input_normals. Throws std::invalid_argument with a
// one-line reason for invalid input or options, std::runtime_error if the solver failed.
Result Denoise(const PointList& points, const Options& options = Options(),
               const PointList* normals = nullptr, const ProgressCallback& progress = nullptr);

// The version of lpd ("0.1.0 (git revision)").
std::string Version();

}  // namespace lpd

#endif  // LPD_DENOISE_H_
