// lpd: the wall seconds of a denoising run's stages (the probe, the graph, the solve, each
// step of the final denoising), by name in the order each first ran. A stage that runs again
// (a second outlier pass) adds to its time. The run summary's "seconds" gives them.
#ifndef LPD_SOLVERS_STAGE_TIMES_H_
#define LPD_SOLVERS_STAGE_TIMES_H_

#include <string>
#include <utility>
#include <vector>

#include "energy/wall_clock.h"

namespace lpd::solvers {

class StageTimes {
 public:
  void Add(const std::string& stage, double seconds) {
    for (auto& [name, total] : stages_) {
      if (name == stage) {
        total += seconds;
        return;
      }
    }
    stages_.emplace_back(stage, seconds);
  }

  // Adds every stage of `other`, in its order.
  void Add(const StageTimes& other) {
    for (const auto& [name, seconds] : other.stages_) Add(name, seconds);
  }

  const std::vector<std::pair<std::string, double>>& stages() const { return stages_; }

 private:
  std::vector<std::pair<std::string, double>> stages_;
};

// Times consecutive stages: each Lap adds the seconds since the last (or since construction)
// to the named stage.
class StageClock {
 public:
  explicit StageClock(StageTimes* times) : times_(times), last_(Clock::now()) {}

  void Lap(const std::string& stage) {
    const Clock::time_point now = Clock::now();
    times_->Add(stage, std::chrono::duration<double>(now - last_).count());
    last_ = now;
  }

 private:
  StageTimes* times_;
  Clock::time_point last_;
};

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_STAGE_TIMES_H_
