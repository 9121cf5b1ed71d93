// lpd: command-line entry point. `lpd COMMAND [ARGS] [--flags]`; `lpd COMMAND --help`.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <map>
#include <new>
#include <string>
#include <vector>

#include <unistd.h>

#include <gflags/gflags.h>

#include "cli/commands.h"
#include "cli/denoise_flags.h"
#include "io/interruption.h"
#include "io/out_of_memory.h"
#include "lpd/denoise.h"
#include "lpd/parameters.h"

namespace {

constexpr int kMaxThreads = 1024;

struct Command {
  int (*run)(const std::vector<std::string>&);
  const char* usage;
  const char* summary;
  std::vector<std::string> flag_files;  // source files whose flags the command reads
};

const std::map<std::string, Command>& Commands() {
  static const std::map<std::string, Command> commands = {
      {"denoise",
       {lpd::cli::RunDenoiseCommand, "lpd denoise [INPUT] -o OUTPUT [flags]",
        "denoise INPUT (.xyz/.ply/.off/.obj) into OUTPUT (.ply/.xyz); with no INPUT, denoise "
        "a built-in noisy box and report its distance to the clean box",
        {"denoise_flags.cc", "denoise_command.cc"}}},
      {"metrics",
       {lpd::cli::RunMetricsCommand, "lpd metrics OUTPUT --ground_truth=SOURCE",
        "MSE, MCD, SNR and exact surface distance of OUTPUT against a mesh, point set or "
        "procedural shape; outlier and feature detection scores with --input=NOISY.ply",
        {"metrics_command.cc", "denoise_flags.cc:threads"}}},
      {"sweep",
       {lpd::cli::RunSweepCommand, "lpd sweep CONFIG.yaml [flags]",
        "run an experiment grid from a YAML config; resumable; CSV and JSON results",
        {"sweep_command.cc", "denoise_flags.cc:threads"}}},
      {"noise",
       {lpd::cli::RunNoiseCommand, "lpd noise [INPUT] -o NOISY.ply [flags]",
        "sample --shape or --mesh (or read INPUT), add seeded noise and labelled outliers",
        {"noise_command.cc", "denoise_command.cc:output", "denoise_command.cc:overwrite",
         "denoise_command.cc:seed"}}},
      {"reconstruct",
       {lpd::cli::RunReconstructCommand, "lpd reconstruct INPUT -o MESH.off [flags]",
        "interpolating surface (Advancing Front or Scale Space, CGAL) through a point set, "
        "as OFF or PLY",
        {"reconstruct_command.cc", "denoise_command.cc:output", "denoise_command.cc:overwrite"}}},
      {"bench",
       {lpd::cli::RunBenchCommand, "lpd bench INPUT [flags]",
        "time every outer iteration of Alg. 1 on INPUT and report peak memory",
        {"denoise_flags.cc"}}},
  };
  return commands;
}

void PrintUsage() {
  std::printf("lpd %s: robust point-set denoising through line processes (Wei et al. 2023)\n\n",
              lpd::Version().c_str());
  for (const auto& [name, command] : Commands()) {
    std::printf("  %-40s %s\n", command.usage, command.summary);
  }
  std::printf("\n`lpd COMMAND --help` lists the command's flags with their defaults.\n");
}

bool FlagBelongsTo(const gflags::CommandLineFlagInfo& flag, const Command& command) {
  for (const std::string& spec : command.flag_files) {
    const size_t colon = spec.find(':');
    const std::string file = spec.substr(0, colon);
    if (flag.filename.size() < file.size() ||
        flag.filename.compare(flag.filename.size() - file.size(), file.size(), file) != 0) {
      continue;
    }
    if (colon == std::string::npos || spec.substr(colon + 1) == flag.name) return true;
  }
  return false;
}

bool IsDenoiseParameter(const std::string& name) {
  const std::vector<std::string>& names = lpd::DenoiseParameterNames();
  return name == "mu_m_deg" || std::find(names.begin(), names.end(), name) != names.end();
}

// The command's own flags, then (for denoise and bench) the method's parameters by group.
void PrintCommandHelp(const Command& command) {
  std::printf("usage: %s\n%s\n\nflags (default in brackets):\n", command.usage, command.summary);
  std::vector<gflags::CommandLineFlagInfo> flags;
  gflags::GetAllFlags(&flags);
  bool has_parameters = false;
  for (const auto& flag : flags) {
    if (!FlagBelongsTo(flag, command)) continue;
    if (IsDenoiseParameter(flag.name)) {
      has_parameters = true;
      continue;
    }
    std::printf("  --%-20s %s [%s]\n", flag.name.c_str(), flag.description.c_str(),
                flag.default_value.c_str());
  }
  if (has_parameters) lpd::cli::PrintParameterHelp();
}

// Waiting OpenMP threads (GNU libgomp) spin for about 300,000 rounds before they sleep,
// which makes lpd several times slower beside other work: FANDISK 0.01 with 2 threads took
// 5.1 s next to one busy core against 3.2 s with 1 thread, and two runs at once 6.1 s
// (docs/performance.md, "Shared machines"). A spin of 1,000 rounds keeps 2 threads within
// 1.1x of 1 thread there and within 5% of spinning on an idle machine; sleeping at once
// (OMP_WAIT_POLICY=PASSIVE) costs 18% when idle. libgomp reads GOMP_SPINCOUNT once, when it
// is loaded, so a run that set neither setting sets it and starts itself again; the results
// do not change.
void RestartWithShortOpenMpSpins(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) {
    return;
  }
  ::setenv("GOMP_SPINCOUNT", "1000", 1);
  ::execv("/proc/self/exe", argv);  // returns only on failure: then run as we are
}

}  // namespace

int main(int argc, char** argv) {
  RestartWithShortOpenMpSpins(argv);
  gflags::SetUsageMessage("lpd COMMAND [ARGS] [--flags]; run `lpd` for the list of commands");
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") ||
      !std::strcmp(argv[1], "help")) {
    PrintUsage();
    return argc < 2 ? 2 : 0;
  }
  const auto found = Commands().find(argv[1]);
  if (found == Commands().end()) {
    std::fprintf(stderr, "lpd: unknown command '%s' (try: lpd --help)\n", argv[1]);
    return 2;
  }
  const Command& command = found->second;
  // Rewrite "-o FILE" as "--output=FILE" and "--save-state" as "--save_state" (flag names
  // may be spelled with hyphens), and catch --help before gflags sees it.
  std::vector<std::string> rewritten = {std::string("lpd ") + argv[1]};
  for (int a = 2; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--help" || arg == "-h" || arg == "-help") {
      PrintCommandHelp(command);
      return 0;
    }
    if (arg == "-o") {
      if (a + 1 >= argc) {
        std::fprintf(stderr, "lpd: -o needs a file name\n");
        return 2;
      }
      rewritten.push_back("--output=" + std::string(argv[++a]));
    } else if (arg.rfind("--", 0) == 0) {
      std::string flag = arg;
      std::replace(flag.begin() + 2, std::find(flag.begin(), flag.end(), '='), '-', '_');
      rewritten.push_back(flag);
    } else {
      rewritten.push_back(arg);
    }
  }
  std::vector<char*> args;
  for (std::string& arg : rewritten) args.push_back(arg.data());
  int count = static_cast<int>(args.size());
  char** pointer = args.data();
  gflags::ParseCommandLineNonHelpFlags(&count, &pointer, /*remove_flags=*/true);
  std::vector<std::string> positional(pointer + 1, pointer + count);
  // Every command's worker threads, bounded before any is started (OpenMP crashes creating
  // 100000 of them; 1024 still runs, slowly).
  std::string threads;
  if (gflags::GetCommandLineOption("threads", &threads) &&
      !(std::atoi(threads.c_str()) >= 1 && std::atoi(threads.c_str()) <= kMaxThreads)) {
    std::fprintf(stderr, "lpd %s: error: --threads must be in [1, %d], got %s\n", argv[1],
                 kMaxThreads, threads.c_str());
    return 2;
  }
  lpd::io::InstallInterruptionHandlers();
  lpd::io::InstallOutOfMemoryHandler();
  try {
    return command.run(positional);
  } catch (const lpd::io::Interrupted& interrupted) {
    std::fprintf(stderr, "lpd %s: %s\n", argv[1], interrupted.what());
    return 128 + interrupted.signal();
  } catch (const std::bad_alloc&) {
    lpd::io::ExitOutOfMemory();  // thrown past the new-handler (Eigen's allocator)
  } catch (const std::exception& error) {
    std::fprintf(stderr, "lpd %s: error: %s\n", argv[1], error.what());
    return 1;
  }
}
