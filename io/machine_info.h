// lpd: a one-line description of the machine results were measured on.
#ifndef LPD_IO_MACHINE_INFO_H_
#define LPD_IO_MACHINE_INFO_H_

#include <string>

namespace lpd::io {

// "HOST, CPU MODEL, N cores" (from gethostname and /proc/cpuinfo where available).
std::string MachineDescription();

}  // namespace lpd::io

#endif  // LPD_IO_MACHINE_INFO_H_
