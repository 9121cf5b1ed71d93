// lpd: the process's peak resident memory (Linux VmHWM), for benchmarks.
#ifndef LPD_EXPERIMENTS_IO_PEAK_MEMORY_H_
#define LPD_EXPERIMENTS_IO_PEAK_MEMORY_H_

namespace lpd::experiments {

// Peak resident set size in bytes, or -1 where /proc/self/status is unavailable.
long long PeakResidentBytes();

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_IO_PEAK_MEMORY_H_
