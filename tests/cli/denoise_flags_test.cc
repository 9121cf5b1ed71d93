// The flags of `lpd denoise` and the sweep keys are one set of parameters with one set of
// defaults: every flag's default is the default DenoiseOptions' value, and flags given on
// the command line win over a preset.
#include "cli/denoise_flags.h"

#include <gtest/gtest.h>

#include "lpd/parameters.h"
#include "lpd/presets.h"

namespace lpd::cli {
namespace {

TEST(DenoiseFlags, EveryParameterIsAFlagWhoseDefaultIsTheStructDefault) {
  const solvers::DenoiseOptions defaults;
  for (const std::string& name : DenoiseParameterNames()) {
    gflags::CommandLineFlagInfo flag;
    ASSERT_TRUE(gflags::GetCommandLineFlagInfo(name.c_str(), &flag)) << "no flag --" << name;
    // Read the flag's default text back through the parameter table, so that "0.5" and
    // "0.50000" compare equal and a choice is checked by name.
    solvers::DenoiseOptions from_flag;
    SetDenoiseParameter(name, flag.default_value, &from_flag);
    EXPECT_EQ(GetDenoiseParameter(name, from_flag), GetDenoiseParameter(name, defaults))
        << "--" << name << " defaults to " << flag.default_value;
  }
}

TEST(DenoiseFlags, NoFlagsGiveTheDefaultPreset) {
  const solvers::DenoiseOptions from_flags = DenoiseOptionsFromFlags();
  const solvers::DenoiseOptions preset = PresetOptions(Preset::kDefault);
  for (const std::string& name : DenoiseParameterNames()) {
    EXPECT_EQ(GetDenoiseParameter(name, from_flags), GetDenoiseParameter(name, preset)) << name;
  }
}

TEST(DenoiseFlags, PaperPresetTakesTheGivenFlagsOverItsOwnValues) {
  gflags::FlagSaver restore_flags_after_the_test;
  gflags::SetCommandLineOption("preset", "paper");
  gflags::SetCommandLineOption("lambda", "2");
  const solvers::DenoiseOptions options = DenoiseOptionsFromFlags();
  const solvers::DenoiseOptions paper = PresetOptions(Preset::kPaper);
  EXPECT_EQ(options.settings.energy.lambda, 2.0);
  EXPECT_EQ(options.settings.energy.eta, 5000.0);
  EXPECT_EQ(options.problem.k, 20);
  EXPECT_FALSE(options.choose_k);
  for (const std::string& name : DenoiseParameterNames()) {
    if (name == "lambda" || name == "threads") continue;
    EXPECT_EQ(GetDenoiseParameter(name, options), GetDenoiseParameter(name, paper)) << name;
  }
}

TEST(DenoiseFlags, AWeightGivenOutrightReplacesItsDataRule) {
  gflags::FlagSaver restore_flags_after_the_test;
  gflags::SetCommandLineOption("eta", "100");
  gflags::SetCommandLineOption("mu_l", "1e-4");
  const solvers::DenoiseOptions options = DenoiseOptionsFromFlags();
  EXPECT_EQ(options.weights.fit_balance, 0.0);
  EXPECT_EQ(options.settings.mu_l_noise_sigmas, 0.0);
  EXPECT_GT(options.weights.smoothing_balance, 0.0);  // lambda was not given
}

}  // namespace
}  // namespace lpd::cli
