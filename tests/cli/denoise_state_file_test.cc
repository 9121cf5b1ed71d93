// Warm restart: a run saved after some iterations and resumed from the file must be the same
// bit for bit as the uninterrupted run; broken files must be rejected with a reason.
#include "cli/denoise_state_file.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "lpd/parameters.h"
#include "test_problems.h"

namespace lpd::cli {
namespace {

std::string TemporaryPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("lpd_state_test_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

solvers::DenoiseOptions RunOptions(int max_iterations) {
  solvers::DenoiseOptions options;
  options.settings.num_threads = 2;
  options.minimizer.max_iterations = max_iterations;
  // Everything that carries state across iterations: the scale-aware mu_l, a continuation
  // still under way at the split, and the energy and motion histories of the stopping tests
  // (the motion test on, too tight to stop these runs).
  options.settings.mu_l_noise_sigmas = 3.0;
  options.minimizer.gnc.target = solvers::GncTarget::kBoth;
  options.minimizer.gnc.factor = 3.0;
  options.minimizer.gnc.stage_iterations = 2;
  options.minimizer.energy_tolerance = 1e-9;
  options.minimizer.motion_tolerance = 1e-9;
  options.settings.energy.mu_m = 1.0 - std::cos(25.0 * M_PI / 180.0);  // not a short decimal
  return options;
}

void ExpectSameBits(const Eigen::Ref<const Eigen::MatrixXd>& a,
                    const Eigen::Ref<const Eigen::MatrixXd>& b, const char* what) {
  ASSERT_EQ(a.rows(), b.rows()) << what;
  ASSERT_EQ(a.cols(), b.cols()) << what;
  EXPECT_EQ(std::memcmp(a.data(), b.data(), sizeof(double) * a.size()), 0) << what;
}

// Runs `points` for 9 iterations in one go, and for 4, saved, read back and resumed for 5,
// both from `start`.
void ExpectResumedRunIsTheUninterruptedRun(const energy::PointList& points,
                                           solvers::Initialization start) {
  const std::string path = TemporaryPath("resume.lpds");
  std::remove(path.c_str());

  solvers::DenoiseOptions full_options = RunOptions(9);
  full_options.initialization = start;
  solvers::DenoiseState full = solvers::StartDenoising(points, full_options);
  const solvers::SolverSummary full_summary = solvers::MinimizeFromState(full_options, &full);
  ASSERT_EQ(full_summary.num_iterations, 9);

  solvers::DenoiseOptions first_options = RunOptions(4);
  first_options.initialization = start;
  solvers::DenoiseState first = solvers::StartDenoising(points, first_options);
  solvers::MinimizeFromState(first_options, &first);
  ASSERT_FALSE(first.progress.gnc.mu_m.AtTarget(first_options.settings.energy.mu_m))
      << "the split should fall inside the continuation";
  WriteDenoiseState(path, first, first_options, /*overwrite=*/false);

  SavedDenoiseRun saved = ReadDenoiseState(path);
  std::remove(path.c_str());
  EXPECT_EQ(saved.num_threads, 2);
  solvers::DenoiseOptions resumed_options;
  for (const auto& [name, value] : saved.parameters) {
    SetDenoiseParameter(name, value, &resumed_options);
  }
  resumed_options.settings.num_threads = saved.num_threads;
  resumed_options.minimizer.max_iterations = 5;
  EXPECT_EQ(resumed_options.settings.energy.mu_m, full_options.settings.energy.mu_m);
  solvers::DenoiseState& resumed = saved.state;
  // The rebuilt problem: same points, graph and weights without a k-NN search.
  EXPECT_EQ(resumed.order, full.order);
  EXPECT_EQ(resumed.problem.graph.pairs, full.problem.graph.pairs);
  EXPECT_EQ(resumed.problem.alpha, full.problem.alpha);
  EXPECT_EQ(resumed.problem.beta, full.problem.beta);
  const solvers::SolverSummary resumed_summary =
      solvers::MinimizeFromState(resumed_options, &resumed);

  EXPECT_EQ(resumed_summary.iterations.front().iteration, 5);
  EXPECT_EQ(resumed_summary.num_iterations, 9);
  ExpectSameBits(resumed.variables.h, full.variables.h, "H");
  ExpectSameBits(resumed.variables.t, full.variables.t, "T");
  ExpectSameBits(resumed.variables.l, full.variables.l, "L");
  ExpectSameBits(resumed.variables.m, full.variables.m, "M");
  ExpectSameBits(resumed.variables.s, full.variables.s, "S");
  EXPECT_EQ(resumed_summary.final_energy.total(), full_summary.final_energy.total());
  EXPECT_EQ(resumed.progress.energy_history, full.progress.energy_history);
  EXPECT_EQ(resumed.progress.motion_history, full.progress.motion_history);
  EXPECT_EQ(resumed.progress.noise_sigma, full.progress.noise_sigma);
}

// From Alg. 1's zero start, whose first T solve averages planes of either orientation: the
// continuation then starts far enough above its target to be under way at the split (from
// the default's oriented planes it ends within 4 iterations on this sphere).
TEST(DenoiseStateFile, ResumedRunIsTheUninterruptedRunBitForBit) {
  ExpectResumedRunIsTheUninterruptedRun(testing::NoisySphere(3000, 0.01, 11),
                                        solvers::Initialization::kZero);
}

// Noise wider than the spacing widens k, and the smoothing balance is scaled back
// (NeighborhoodSize::smoothing_scale): the saved balance must be the scaled one.
TEST(DenoiseStateFile, ResumesWithTheSmoothingBalanceScaledForWidenedNeighbourhoods) {
  const energy::PointList points = testing::NoisySphere(3000, 0.2, 12);
  EXPECT_LT(solvers::StartDenoising(points, RunOptions(1)).neighborhood.smoothing_scale, 1.0);
  ExpectResumedRunIsTheUninterruptedRun(points, solvers::Initialization::kPlaneFit);
}

TEST(DenoiseStateFile, RejectsBrokenFilesAndKeepsExistingOnes) {
  const energy::PointList points = testing::NoisySphere(500, 0.01, 12);
  const solvers::DenoiseOptions options = RunOptions(1);
  solvers::DenoiseState state = solvers::StartDenoising(points, options);
  solvers::MinimizeFromState(options, &state);
  const std::string path = TemporaryPath("broken.lpds");
  std::remove(path.c_str());
  WriteDenoiseState(path, state, options, false);
  EXPECT_THROW(WriteDenoiseState(path, state, options, false), std::runtime_error);

  const auto size = std::filesystem::file_size(path);
  auto expect_rejected = [&](const std::string& reason) {
    try {
      ReadDenoiseState(path);
      ADD_FAILURE() << "accepted a file that should fail with: " << reason;
    } catch (const std::runtime_error& error) {
      EXPECT_NE(std::string(error.what()).find(reason), std::string::npos) << error.what();
    }
  };
  auto write_at = [&](std::streamoff offset, const void* bytes, size_t count) {
    std::fstream file(path, std::ios::binary | std::ios::in | std::ios::out);
    file.seekp(offset);
    file.write(static_cast<const char*>(bytes), static_cast<std::streamsize>(count));
  };
  EXPECT_NO_THROW(ReadDenoiseState(path));
  // One changed byte anywhere is caught by the checksum (here in the saved points)...
  const char flipped = 0x5a;
  write_at(static_cast<std::streamoff>(size / 2), &flipped, 1);
  expect_rejected("checksum mismatch");
  // ...and a field out of its range by its own check first: 100000 threads (after the 8-byte
  // magic, the version and the byte-order mark).
  std::remove(path.c_str());
  WriteDenoiseState(path, state, options, false);
  const int32_t threads = 100000;
  write_at(16, &threads, sizeof(threads));
  expect_rejected("thread count 100000");
  // Versions 3 and 4 have no checksum, and versions 3-5 no motion test: before the end mark
  // a version-6 state keeps the noise deviation, the motions' count and the motions. A
  // version-3 state (from before the progress test) resumes with that test off, and states
  // older than 6 with the motion test off; versions outside 3-6 are refused.
  std::remove(path.c_str());
  WriteDenoiseState(path, state, options, false);
  {
    std::string bytes(size, '\0');
    std::ifstream(path, std::ios::binary).read(bytes.data(), bytes.size());
    const size_t motions = state.progress.motion_history.size();
    const size_t end_mark = size - 2 * sizeof(uint64_t);
    const size_t motion_fields = sizeof(double) + sizeof(uint32_t) + motions * sizeof(double);
    bytes.erase(end_mark - motion_fields, motion_fields);
    bytes.resize(bytes.size() - sizeof(uint64_t));  // the checksum
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), bytes.size());
  }
  auto set_version = [&](uint32_t version) { write_at(8, &version, sizeof(version)); };
  set_version(3);
  {
    const SavedDenoiseRun old = ReadDenoiseState(path);
    solvers::DenoiseOptions resumed;
    ASSERT_FALSE(old.parameters.empty());
    EXPECT_EQ(old.parameters.front().first, "progress_tolerance");
    SetDenoiseParameter(old.parameters.front().first, old.parameters.front().second, &resumed);
    EXPECT_EQ(resumed.minimizer.progress_tolerance, 0.0);
  }
  set_version(7);
  expect_rejected("state file version 7");
  set_version(4);
  {
    const SavedDenoiseRun old = ReadDenoiseState(path);
    EXPECT_NE(old.parameters.front().first, "progress_tolerance");
    solvers::DenoiseOptions resumed;
    for (const auto& [name, value] : old.parameters) SetDenoiseParameter(name, value, &resumed);
    EXPECT_EQ(resumed.minimizer.motion_tolerance, 0.0);
    EXPECT_TRUE(std::isnan(old.state.progress.noise_sigma));
    EXPECT_EQ(old.state.progress.motion_history.size(),
              old.state.progress.energy_history.size());
  }
  std::filesystem::resize_file(path, size / 2);
  expect_rejected("truncated");
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << "x y z\n1 2 3\n";
  }
  expect_rejected("not an lpd state file");
  std::remove(path.c_str());
  expect_rejected("cannot open");
}

}  // namespace
}  // namespace lpd::cli
