// lpd: what a `lpd denoise` run did, for the files it writes: the --summary_json record
// (parameters given and in effect, what was derived from the data, every pass, counts that
// match the output file, times, version) and the output PLY's header comments.
#ifndef LPD_CLI_RUN_SUMMARY_H_
#define LPD_CLI_RUN_SUMMARY_H_

#include <string>
#include <utility>
#include <vector>

#include "solvers/denoise_point_set.h"

namespace lpd::cli {

struct RunDescription {
  std::string version;   // lpd's
  std::string input;     // file name, "-" or "built-in box"
  std::string output;    // file name, "-" or ""
  std::string preset;
  // The parameters given (flags, or the saved state's and the flags on --resume).
  std::vector<std::pair<std::string, std::string>> given;
};

// The summary as one JSON object. `output_points`: the points written.
std::string RunSummaryJson(const RunDescription& run, const solvers::DenoiseOptions& options,
                           const solvers::DenoiseResult& result, size_t output_points);

// PLY header comments: the version, every parameter in effect, and what was derived.
std::vector<std::string> RunHeaderComments(const RunDescription& run,
                                           const solvers::DenoiseOptions& options,
                                           const solvers::DenoiseResult& result);

}  // namespace lpd::cli

#endif  // LPD_CLI_RUN_SUMMARY_H_
