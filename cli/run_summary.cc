#include "cli/run_summary.h"

#include <cstdio>

#include "io/json.h"
#include "lpd/parameters.h"

namespace lpd::cli {
namespace {

using io::JsonNumber;
using io::JsonString;

std::string Integer(long long value) { return std::to_string(value); }

// Every parameter that applies to the run's solver, with its value in effect.
std::vector<std::pair<std::string, std::string>> ParametersInEffect(
    const solvers::DenoiseOptions& options) {
  std::vector<std::pair<std::string, std::string>> values;
  for (const std::string& name : DenoiseParameterNames()) {
    if (DenoiseParameterApplies(name, options.solver)) {
      values.emplace_back(name, GetDenoiseParameter(name, options));
    }
  }
  return values;
}

// The values a run derived from the data (or was given), as (name, JSON number).
std::vector<std::pair<std::string, std::string>> Derived(const solvers::DenoiseOptions& options,
                                                         const solvers::DenoiseResult& result) {
  return {{"k", Integer(result.neighborhood.k)},
          {"noise_sigma", JsonNumber(result.neighborhood.noise_sigma)},
          {"read_sigma", JsonNumber(result.neighborhood.read_sigma)},
          {"spacing", JsonNumber(result.neighborhood.spacing)},
          {"k_radius_sigmas", JsonNumber(result.neighborhood.radius_in_sigmas)},
          {"smoothing_scale", JsonNumber(result.neighborhood.smoothing_scale)},
          {"two_sheet_fraction", JsonNumber(result.neighborhood.two_sheet_fraction)},
          {"thin_candidate_fraction", JsonNumber(result.neighborhood.thin_candidate_fraction)},
          {"eta", JsonNumber(result.summary.eta)},
          {"lambda", JsonNumber(result.summary.lambda)},
          {"mu_l", JsonNumber(result.summary.mu_l)},
          {"mu_m", JsonNumber(options.settings.energy.mu_m)}};
}

}  // namespace

std::string RunSummaryJson(const RunDescription& run, const solvers::DenoiseOptions& options,
                           const solvers::DenoiseResult& result, size_t output_points) {
  std::vector<std::pair<std::string, std::string>> given, effect;
  for (const auto& [name, value] : run.given) given.emplace_back(name, JsonString(value));
  for (const auto& [name, value] : ParametersInEffect(options)) {
    effect.emplace_back(name, JsonString(value));
  }
  std::vector<std::string> passes;
  for (const solvers::PassSummary& pass : result.pass_summaries) {
    passes.push_back(io::JsonObject(
        {{"points", Integer(pass.points)},
         {"solved_points", Integer(pass.solved_points)},
         {"k", Integer(pass.k)},
         {"iterations", Integer(pass.iterations)},
         {"termination", JsonString(solvers::TerminationTypeName(pass.termination))}}));
  }
  std::vector<std::pair<std::string, std::string>> stages;
  for (const auto& [stage, seconds] : result.stage_times.stages()) {
    stages.emplace_back(stage, JsonNumber(seconds));
  }
  long long features = 0;
  for (size_t i = 0; i < result.kept.size(); ++i) {
    features += result.kept[i] && result.indicators.is_feature[i];
  }
  const std::string counts = io::JsonObject(
      {{"input_points", Integer(static_cast<long long>(result.projected.size()))},
       {"output_points", Integer(static_cast<long long>(output_points))},
       {"outliers_flagged", Integer(result.num_outliers)},
       {"isolated", Integer(result.num_isolated)},
       {"far", Integer(result.num_far)},
       {"duplicates", Integer(result.num_duplicates)},
       {"near_repeats", Integer(result.num_near_repeats)},
       {"separated", Integer(result.num_separated)},
       {"removed", Integer(result.num_removed)},
       {"output_feature_points", Integer(features)}});
  return io::JsonObject(
      {{"lpd_version", JsonString(run.version)},
       {"input", JsonString(run.input)},
       {"output", JsonString(run.output)},
       {"preset", JsonString(run.preset)},
       {"solver", JsonString(solvers::SolverName(options.solver))},
       {"threads", Integer(options.settings.num_threads)},
       {"parameters_given", io::JsonObject(given)},
       {"parameters", io::JsonObject(effect)},
       {"derived", io::JsonObject(Derived(options, result))},
       {"subsampled", result.subsampled ? "true" : "false"},
       {"passes", io::JsonArray(passes)},
       {"termination", JsonString(solvers::TerminationTypeName(result.summary.termination))},
       {"message", JsonString(result.summary.message)},
       {"note", JsonString(result.removal_note)},
       {"counts", counts},
       {"seconds", io::JsonObject({{"total", JsonNumber(result.total_seconds)},
                                   {"setup", JsonNumber(result.setup_seconds)},
                                   {"stages", io::JsonObject(stages)}})}});
}

std::vector<std::string> RunHeaderComments(const RunDescription& run,
                                           const solvers::DenoiseOptions& options,
                                           const solvers::DenoiseResult& result) {
  std::string parameters = "lpd parameters preset=" + run.preset +
                           " solver=" + solvers::SolverName(options.solver);
  for (const auto& [name, value] : ParametersInEffect(options)) {
    parameters += " " + name + "=" + value;
  }
  std::string derived = "lpd derived";
  for (const auto& [name, value] : Derived(options, result)) derived += " " + name + "=" + value;
  // A header line ends at a line break: none may come from a file name.
  std::string input = run.input;
  for (char& c : input) {
    if (static_cast<unsigned char>(c) < 0x20) c = '?';
  }
  return {"lpd " + run.version + " denoise " + input, parameters, derived};
}

}  // namespace lpd::cli
