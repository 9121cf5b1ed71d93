// lpd: a one-line description of the machine results were measured on.
#ifndef LPD_EXPERIMENTS_IO_MACHINE_INFO_H_
#define LPD_EXPERIMENTS_IO_MACHINE_INFO_H_

#include <string>

namespace lpd::experiments {

// "HOST, CPU MODEL, N cores" (from gethostname and /proc/cpuinfo where available).
std::string MachineDescription();

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_IO_MACHINE_INFO_H_
