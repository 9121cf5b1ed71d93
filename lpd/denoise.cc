#include "lpd/denoise.h"

#include <algorithm>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "lpd/options.h"
#include "lpd/parameters.h"
#include "lpd/presets.h"
#include "lpd/source_revision.h"
#include "solvers/denoise_point_set.h"

namespace lpd {
namespace {

// Shortest text that reads back as exactly `value`.
std::string NumberText(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

Summary MakeSummary(const solvers::DenoiseResult& run, const solvers::DenoiseOptions& options,
                    int64_t output_points) {
  Summary summary;
  summary.version = Version();
  summary.termination = solvers::TerminationTypeName(run.summary.termination);
  summary.message = run.summary.message;
  summary.stopped = run.summary.termination == solvers::TerminationType::kUserAbort;
  summary.iterations = run.summary.num_iterations;
  summary.passes = run.passes;
  summary.k = run.neighborhood.k;
  summary.noise_sigma = run.neighborhood.noise_sigma;
  summary.read_sigma = run.neighborhood.read_sigma;
  summary.spacing = run.neighborhood.spacing;
  summary.eta = run.summary.eta;
  summary.lambda = run.summary.lambda;
  summary.mu_l = run.summary.mu_l;
  summary.mu_m = options.settings.energy.mu_m;
  summary.input_points = static_cast<int64_t>(run.projected.size());
  summary.output_points = output_points;
  summary.outliers = run.num_outliers;
  summary.isolated = run.num_isolated;
  summary.far = run.num_far;
  summary.duplicates = run.num_duplicates;
  summary.near_repeats = run.num_near_repeats;
  summary.separated = run.num_separated;
  summary.removed = run.num_removed;
  summary.features = run.num_features;
  summary.solved_points = run.solved_points;
  summary.note = run.removal_note;
  summary.seconds = run.total_seconds;
  summary.setup_seconds = run.setup_seconds;
  summary.stage_seconds = run.stage_times.stages();
  return summary;
}

Result MakeResult(const solvers::DenoiseResult& run, const solvers::DenoiseOptions& options) {
  Result result;
  for (size_t i = 0; i < run.projected.size(); ++i) {
    if (!run.kept[i]) continue;
    result.points.push_back(run.projected[i]);
    result.normals.push_back(run.normals[i]);
    result.source_index.push_back(static_cast<int64_t>(i));
    result.outlier_score.push_back(static_cast<float>(run.indicators.outlier_score[i]));
    result.feature_score.push_back(static_cast<float>(run.indicators.feature_score[i]));
    result.is_outlier.push_back(run.indicators.is_outlier[i]);
    result.is_feature.push_back(run.indicators.is_feature[i]);
  }
  result.summary = MakeSummary(run, options, static_cast<int64_t>(result.points.size()));
  return result;
}

// The solvers' per-iteration records as Progress, counting passes: a pass starts again at
// iteration 1.
solvers::IterationCallback ProgressAdapter(const ProgressCallback& progress) {
  if (!progress) return nullptr;
  auto last_iteration = std::make_shared<int>(0);
  auto pass = std::make_shared<int>(1);
  return [progress, last_iteration, pass](const solvers::IterationRecord& record) {
    if (record.iteration <= *last_iteration) ++*pass;
    *last_iteration = record.iteration;
    return progress({*pass, record.iteration, record.energy.total(), record.point_motion});
  };
}

}  // namespace

Options::Options(const std::string& preset) : preset_(preset) {
  Preset parsed;
  if (!ParsePreset(preset, &parsed)) {
    throw std::invalid_argument("preset must be default or paper, got '" + preset + "'");
  }
}

Options& Options::Set(const std::string& name, const std::string& value) {
  // Checked on a copy now, so that the error names the call that caused it.
  Options checked = *this;
  checked.given_.emplace_back(name, value);
  ResolveOptions(checked);
  given_ = std::move(checked.given_);
  return *this;
}

Options& Options::Set(const std::string& name, const char* value) {
  return Set(name, std::string(value));
}

Options& Options::Set(const std::string& name, double value) {
  return Set(name, NumberText(value));
}

Options& Options::Set(const std::string& name, int value) {
  return Set(name, std::to_string(value));
}

Options& Options::Set(const std::string& name, bool value) {
  return Set(name, std::string(value ? "true" : "false"));
}

std::string Options::Get(const std::string& name) const {
  return GetDenoiseParameter(name, ResolveOptions(*this));
}

Result Denoise(const PointList& points, const Options& options, const PointList* normals,
               const ProgressCallback& progress) {
  const solvers::DenoiseOptions resolved = ResolveOptions(options);
  for (size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) {
      throw std::invalid_argument("point " + std::to_string(i) + " is not finite");
    }
  }
  solvers::DenoiseHooks hooks;
  hooks.progress = ProgressAdapter(progress);
  const solvers::DenoiseResult run = solvers::DenoisePointSet(points, resolved, hooks, normals);
  return MakeResult(run, resolved);
}

std::string Version() { return std::string(LPD_VERSION) + " (" + SourceRevision() + ")"; }

}  // namespace lpd
