// lpd: the process's peak resident memory (Linux VmHWM), for benchmarks.
#ifndef LPD_IO_PEAK_MEMORY_H_
#define LPD_IO_PEAK_MEMORY_H_

namespace lpd::io {

// Peak resident set size in bytes, or -1 where /proc/self/status is unavailable.
long long PeakResidentBytes();

}  // namespace lpd::io

#endif  // LPD_IO_PEAK_MEMORY_H_
