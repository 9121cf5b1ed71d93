// lpd: SIGINT and SIGTERM stop a run promptly and leave no partial output.
//
// The first signal sets a flag that the commands poll at safe points (every iteration of the
// solver, every sweep cell, between stages): they stop there, their AtomicOutputFiles remove
// their temporary files on the way out, and lpd exits with 128 + the signal's number. Where a
// stage has no such point (a k-NN build, a CGAL reconstruction), a watchdog armed by the first
// signal removes every registered temporary file and exits the same way one second later. A
// second signal exits at once, also after removing them.
#ifndef LPD_IO_INTERRUPTION_H_
#define LPD_IO_INTERRUPTION_H_

#include <stdexcept>
#include <string>

namespace lpd::io {

// Installs the handlers for SIGINT and SIGTERM, and ignores SIGXFSZ so that exceeding the
// file-size limit is a write error (once per process; later calls do nothing).
void InstallInterruptionHandlers();

// The signal that asked the run to stop, or 0.
int InterruptionSignal();
inline bool InterruptionRequested() { return InterruptionSignal() != 0; }

// Thrown at a safe point after a signal; main turns it into exit status 128 + signal.
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal);
  int signal() const { return signal_; }

 private:
  int signal_;
};

// Throws Interrupted if a signal arrived.
void ThrowIfInterrupted();

// Temporary files that the watchdog removes before a forced exit, and temporary directories,
// removed after the files when they are empty then. RegisterTemporaryFile returns a slot for
// UnregisterTemporaryFile, or -1 when all slots are taken (then the file is only removed by
// its owner).
int RegisterTemporaryFile(const std::string& path);
void UnregisterTemporaryFile(int slot);

// Removes every registered temporary file, then the registered directories that are empty
// (async-signal-safe and allocation-free: for handlers that end the process).
void RemoveTemporaryFiles();

}  // namespace lpd::io

#endif  // LPD_IO_INTERRUPTION_H_
