// lpd: the subcommands of the `lpd` command line. Each takes the positional arguments left
// after flag parsing and returns the process exit code; errors are reported by throwing.
#ifndef LPD_CLI_COMMANDS_H_
#define LPD_CLI_COMMANDS_H_

#include <string>
#include <vector>

namespace lpd::cli {

int RunDenoiseCommand(const std::vector<std::string>& arguments);
int RunMetricsCommand(const std::vector<std::string>& arguments);
int RunBenchCommand(const std::vector<std::string>& arguments);
int RunNoiseCommand(const std::vector<std::string>& arguments);
int RunReconstructCommand(const std::vector<std::string>& arguments);
int RunSweepCommand(const std::vector<std::string>& arguments);

}  // namespace lpd::cli

#endif  // LPD_CLI_COMMANDS_H_
