// Every parameter is declared once (lpd/parameters.cc): its flag, --help line, sweep key,
// saved-state field, paper value and public-API option all come from that declaration.
#include <cstdlib>
#include <filesystem>
#include <string>

#include <unistd.h>

#include <gflags/gflags.h>
#include <gtest/gtest.h>

#include "cli/denoise_flags.h"
#include "cli/denoise_state_file.h"
#include "experiments/sweep/sweep_methods.h"
#include "lpd/denoise.h"
#include "lpd/parameters.h"
#include "lpd/presets.h"
#include "test_problems.h"

namespace lpd {
namespace {

TEST(ParameterDeclarations, EachIsAFlagWithItsHelpAndTheDefaultOptionsValue) {
  const solvers::DenoiseOptions defaults;
  for (const ParameterInfo& parameter : DenoiseParameters()) {
    gflags::CommandLineFlagInfo flag;
    ASSERT_TRUE(gflags::GetCommandLineFlagInfo(parameter.name.c_str(), &flag))
        << "no flag --" << parameter.name;
    EXPECT_EQ(flag.description.rfind(parameter.help, 0), 0u) << parameter.name;
    if (!parameter.auto_rule.empty()) {
      EXPECT_NE(flag.description.find("auto: " + parameter.auto_rule), std::string::npos);
    }
    if (parameter.kind == ParameterKind::kFlag) {
      EXPECT_EQ(flag.default_value, GetDenoiseParameter(parameter.name, defaults));
    } else {
      EXPECT_EQ(flag.default_value, GetDenoiseParameter(parameter.name, defaults))
          << parameter.name;
    }
  }
  // The four weights derived from the data show it as their default.
  for (const char* name : {"k", "eta", "lambda", "mu_l"}) {
    EXPECT_EQ(gflags::GetCommandLineFlagInfoOrDie(name).default_value, "auto") << name;
  }
}

TEST(ParameterDeclarations, HelpListsEachUnderItsGroup) {
  ::testing::internal::CaptureStdout();
  cli::PrintParameterHelp();
  const std::string help = ::testing::internal::GetCapturedStdout();
  for (const ParameterInfo& parameter : DenoiseParameters()) {
    const size_t group = help.find("\n" + parameter.group + ":\n");
    const size_t line = help.find("  --" + parameter.name + " ");
    ASSERT_NE(group, std::string::npos) << parameter.group;
    ASSERT_NE(line, std::string::npos) << parameter.name;
    EXPECT_LT(group, line) << parameter.name;
    if (!parameter.paper_value.empty()) {
      EXPECT_NE(help.find("paper: " + parameter.paper_value, line), std::string::npos);
    }
  }
  EXPECT_NE(help.find("--lambda"), std::string::npos);
  EXPECT_NE(help.find("[auto]"), std::string::npos);
}

TEST(ParameterDeclarations, ThePaperPresetIsTheDefaultWithTheDeclaredPaperValues) {
  const solvers::DenoiseOptions defaults;
  const solvers::DenoiseOptions paper = PresetOptions(Preset::kPaper);
  for (const ParameterInfo& parameter : DenoiseParameters()) {
    if (parameter.name == "mu_m_deg") continue;  // a second spelling of mu_m
    solvers::DenoiseOptions expected = defaults;
    if (!parameter.paper_value.empty()) {
      SetDenoiseParameter(parameter.name, parameter.paper_value, &expected);
    }
    EXPECT_EQ(GetDenoiseParameter(parameter.name, paper),
              GetDenoiseParameter(parameter.name, expected))
        << parameter.name;
  }
  // Table 2 of the paper, independently of the declarations.
  EXPECT_EQ(paper.problem.k, 20);
  EXPECT_FALSE(paper.choose_k);
  EXPECT_EQ(paper.settings.energy.lambda, 1.0);
  EXPECT_EQ(paper.settings.energy.eta, 5000.0);
  EXPECT_EQ(paper.settings.energy.mu_l, 5e-9);
  EXPECT_EQ(paper.settings.energy.mu_m, 0.13);
  EXPECT_EQ(paper.minimizer.max_iterations, 5);
  // Alg. 1 from H = T = 0 as published, where the default starts from oriented PCA planes;
  // the joint solve starts from those planes in both.
  EXPECT_EQ(paper.EffectiveInitialization(), solvers::Initialization::kZero);
  EXPECT_EQ(defaults.EffectiveInitialization(), solvers::Initialization::kPlaneFit);
  solvers::DenoiseOptions paper_ceres = paper;
  paper_ceres.solver = solvers::Solver::kCeres;
  EXPECT_EQ(paper_ceres.EffectiveInitialization(), solvers::Initialization::kPlaneFit);
  std::string error;
  EXPECT_TRUE(paper_ceres.IsValid(&error)) << error;
}

// Texts of the same value: equal numbers ("4.4" and "4.400000"), or equal words.
bool SameValue(const std::string& a, const std::string& b) {
  char* end_a = nullptr;
  char* end_b = nullptr;
  const double x = std::strtod(a.c_str(), &end_a);
  const double y = std::strtod(b.c_str(), &end_b);
  if (!a.empty() && !b.empty() && *end_a == '\0' && *end_b == '\0') return x == y;
  return a == b;
}

// A value of `parameter` other than its default, valid for it.
std::string OtherValue(const ParameterInfo& parameter, const solvers::DenoiseOptions& defaults) {
  const std::string current = GetDenoiseParameter(parameter.name, defaults);
  switch (parameter.kind) {
    case ParameterKind::kFlag: return current == "true" ? "false" : "true";
    case ParameterKind::kInteger: return current == "auto" ? "25" : std::to_string(std::stoi(current) + 1);
    case ParameterKind::kNumber: {
      if (current == "auto") return "0.5";
      const double value = std::stod(current);
      if (value == 0.0) return "2";
      return std::to_string(value < 0.5 ? value * 1.5 : value + 0.25);
    }
    case ParameterKind::kChoice: break;
  }
  static const std::pair<const char*, const char*> kChoices[] = {
      {"initialization", "plane_fit"}, {"gnc", "mu_l"}, {"preconditioner", "jacobi"},
      {"projection", "plane"}, {"ceres_orientations", "closed_form"},
      {"ceres_linear_solver", "cgnr"}, {"outliers", "mark"}};
  for (const auto& [name, value] : kChoices) {
    if (parameter.name == name) return value;
  }
  ADD_FAILURE() << "no other value known for choice " << parameter.name;
  return current;
}

TEST(ParameterDeclarations, EachIsASweepKeyAnOptionAndAStateField) {
  const solvers::DenoiseOptions defaults;
  const energy::PointList points = testing::NoisyPlane(400, 0.002, 3);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("lpd_declarations_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (const ParameterInfo& parameter : DenoiseParameters()) {
    if (parameter.name == "mu_m_deg") continue;
    const std::string value = OtherValue(parameter, defaults);
    const bool ceres = parameter.scope == ParameterScope::kCeres;
    // The public API (and so the Python module) takes it by name.
    Options options;
    options.solver = ceres ? "ceres" : "alternating";
    options.Set(parameter.name, value);
    EXPECT_TRUE(SameValue(options.Get(parameter.name), value)) << parameter.name;
    // A sweep takes it as a key of a method.
    experiments::MethodConfig method;
    method.method = ceres ? "ceres" : "lpd";
    method.parameters[parameter.name].text = value;
    bool found = false;
    for (const auto& [name, effective] : experiments::EffectiveParameters(method)) {
      if (name != parameter.name) continue;
      found = true;
      EXPECT_TRUE(SameValue(effective, value)) << parameter.name << ": " << effective;
    }
    EXPECT_TRUE(found) << parameter.name << " is not a sweep column";
    // A saved state keeps it.
    if (ceres) continue;  // saved states are of Alg. 1 runs here
    solvers::DenoiseOptions run = defaults;
    run.choose_k = false;
    run.problem.k = 12;
    run.settings.num_threads = 1;
    SetDenoiseParameter(parameter.name, value, &run);
    run.choose_k = false;  // the state is made at k 12 whatever the parameter says
    solvers::DenoiseState state = solvers::StartDenoising(points, run);
    const std::string path = (dir / (parameter.name + ".lpds")).string();
    cli::WriteDenoiseState(path, state, run, /*overwrite=*/true);
    const cli::SavedDenoiseRun saved = cli::ReadDenoiseState(path);
    found = false;
    for (const auto& [name, text] : saved.parameters) {
      if (name != parameter.name) continue;
      found = true;
      if (parameter.name != "k") {
        EXPECT_TRUE(SameValue(text, value)) << parameter.name;
      }
    }
    EXPECT_TRUE(found) << parameter.name << " is not saved in a state";
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lpd
