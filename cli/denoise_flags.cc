#include "cli/denoise_flags.h"

#include <cstdio>
#include <deque>
#include <stdexcept>
#include <thread>

#include "lpd/parameters.h"
#include "lpd/presets.h"

DEFINE_string(preset, "default",
              "default (k, eta, lambda, mu_l from the data; run to convergence; sphere "
              "projection) or paper (the paper's literal Table 2 setting: k = 20, lambda = 1, "
              "eta = 5000, mu_l = 5e-9, 5 iterations, plane projection); flags given with it "
              "override its values");
DEFINE_string(solver, "alternating",
              "alternating (Alg. 1, the paper's method) or ceres (the joint solve, the "
              "validation solver: Eq. 5 minimized over H, T, S at once by Ceres)");
DEFINE_int32(threads, static_cast<int>(std::max(1u, std::thread::hardware_concurrency())),
             "worker threads (default: all cores)");

namespace lpd::cli {
namespace {

// A flag registered from a parameter's declaration. gflags keeps pointers to the name, the
// help text and the storage, so these live as long as the program (a deque never moves
// its elements).
struct ParameterFlag {
  std::string name;
  std::string help;
  std::string value;          // every kind but kFlag: the text SetDenoiseParameter reads
  std::string default_value;
  bool switch_value = false;  // kFlag, so that `--snap_features` and `--nosnap_features` work
  bool switch_default = false;
};

std::deque<ParameterFlag>& ParameterFlags() {
  static std::deque<ParameterFlag> flags;
  return flags;
}

// What --help says of a parameter after its help text: its data rule and the paper's value.
std::string HelpSuffix(const ParameterInfo& parameter) {
  std::string suffix;
  if (!parameter.auto_rule.empty()) suffix += "auto: " + parameter.auto_rule;
  if (!parameter.paper_value.empty()) {
    suffix += (suffix.empty() ? "" : "; ") + std::string("paper: ") + parameter.paper_value;
  }
  return suffix.empty() ? suffix : " (" + suffix + ")";
}

// One flag per declared parameter, with the default DenoiseOptions' value as its default.
bool RegisterParameterFlags() {
  const solvers::DenoiseOptions defaults;
  for (const ParameterInfo& parameter : DenoiseParameters()) {
    ParameterFlag& flag = ParameterFlags().emplace_back();
    flag.name = parameter.name;
    flag.help = parameter.help + HelpSuffix(parameter);
    const std::string value = GetDenoiseParameter(parameter.name, defaults);
    if (parameter.kind == ParameterKind::kFlag) {
      flag.switch_value = flag.switch_default = value == "true";
      gflags::FlagRegisterer(flag.name.c_str(), flag.help.c_str(), __FILE__, &flag.switch_value,
                             &flag.switch_default);
    } else {
      flag.value = flag.default_value = value;
      gflags::FlagRegisterer(flag.name.c_str(), flag.help.c_str(), __FILE__, &flag.value,
                             &flag.default_value);
    }
  }
  return true;
}

const bool kParameterFlagsRegistered = RegisterParameterFlags();

// A weight given outright under the default preset replaces the value derived from the data;
// the paper's raw values (lambda = 1, eta = 5000, mu_l = 5e-9) belong to the paper's
// normalization and neighbourhoods, and give far worse results under the default's.
void WarnAboutRawWeights(const std::vector<std::pair<std::string, std::string>>& given) {
  static const std::pair<const char*, const char*> kRules[] = {
      {"lambda", "--smoothing_balance"}, {"eta", "--fit_balance"},
      {"mu_l", "--mu_l_noise_sigmas"}};
  for (const auto& [name, value] : given) {
    for (const auto& [weight, rule] : kRules) {
      if (name != weight || value == "auto") continue;
      std::fprintf(stderr,
                   "note: --%s=%s replaces the value derived from the data; it is an absolute "
                   "weight in the frame normalized to diagonal 1. To scale the derived value "
                   "give %s; for the paper's setting give --preset=paper\n",
                   weight, value.c_str(), rule);
    }
  }
}

}  // namespace

std::vector<std::pair<std::string, std::string>> GivenParameters() {
  std::vector<std::pair<std::string, std::string>> given;
  for (const ParameterInfo& parameter : DenoiseParameters()) {
    const gflags::CommandLineFlagInfo flag =
        gflags::GetCommandLineFlagInfoOrDie(parameter.name.c_str());
    if (!flag.is_default) given.emplace_back(parameter.name, flag.current_value);
  }
  return given;
}

bool FlagGiven(const char* name) { return !gflags::GetCommandLineFlagInfoOrDie(name).is_default; }

solvers::DenoiseOptions DenoiseOptionsFromFlags(
    const std::vector<std::pair<std::string, std::string>>* saved) {
  Preset preset;
  if (!ParsePreset(FLAGS_preset, &preset)) {
    throw std::invalid_argument("--preset must be default or paper, got '" + FLAGS_preset + "'");
  }
  solvers::DenoiseOptions options = PresetOptions(preset);
  if (!solvers::ParseSolver(FLAGS_solver, &options.solver)) {
    throw std::invalid_argument("--solver must be alternating or ceres, got '" + FLAGS_solver +
                                "'");
  }
  if (saved) {
    for (const auto& [name, value] : *saved) SetDenoiseParameter(name, value, &options);
  }
  const std::vector<std::pair<std::string, std::string>> given = GivenParameters();
  RefuseConflictingParameters(given);
  for (const auto& [name, value] : given) {
    if (!DenoiseParameterApplies(name, options.solver)) {
      throw std::invalid_argument("--" + name + " has no effect with --solver=" + FLAGS_solver);
    }
    SetDenoiseParameter(name, value, &options);
  }
  options.settings.num_threads = FLAGS_threads;
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument(error);
  if (preset == Preset::kDefault && !saved) WarnAboutRawWeights(given);
  return options;
}

void PrintParameterHelp() {
  const solvers::DenoiseOptions defaults;
  std::string group;
  for (const ParameterInfo& parameter : DenoiseParameters()) {
    if (parameter.group != group) {
      group = parameter.group;
      std::printf("\n%s:\n", group.c_str());
    }
    std::printf("  --%-20s %s [%s]\n", parameter.name.c_str(),
                (parameter.help + HelpSuffix(parameter)).c_str(),
                GetDenoiseParameter(parameter.name, defaults).c_str());
  }
}

}  // namespace lpd::cli
