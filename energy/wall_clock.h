// lpd: wall-clock timing of the solvers' stages and the commands.
#ifndef LPD_ENERGY_WALL_CLOCK_H_
#define LPD_ENERGY_WALL_CLOCK_H_

#include <chrono>

namespace lpd {

using Clock = std::chrono::steady_clock;

inline double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace lpd

#endif  // LPD_ENERGY_WALL_CLOCK_H_
