// lpd: reads one method's parameters from a sweep config, by name with defaults.
//
// Each accessor checks its value's type and range, records the effective value (given or
// default) for the results, and marks the name as known; Finish() then rejects any given
// parameter no accessor asked for. Errors are std::invalid_argument naming the method and
// the parameter.
#ifndef LPD_EXPERIMENTS_SWEEP_METHOD_PARAMETERS_H_
#define LPD_EXPERIMENTS_SWEEP_METHOD_PARAMETERS_H_

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "experiments/sweep/sweep_config.h"

namespace lpd::experiments {

class MethodParameters {
 public:
  explicit MethodParameters(const MethodConfig& method) : method_(method) {}

  int Integer(const std::string& name, int fallback, int min);
  double Number(const std::string& name, double fallback, double min, double max);
  // One of `choices` (listed in error messages).
  std::string Choice(const std::string& name, const std::string& fallback,
                     const std::vector<std::string>& choices);

  // Throws for a given parameter that no accessor asked for; returns the effective values
  // in the order they were asked for.
  std::vector<std::pair<std::string, std::string>> Finish() const;

 private:
  const std::string* Given(const std::string& name);
  [[noreturn]] void Fail(const std::string& name, const std::string& reason) const;

  const MethodConfig& method_;
  std::set<std::string> known_;
  std::vector<std::pair<std::string, std::string>> effective_;
};

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_SWEEP_METHOD_PARAMETERS_H_
