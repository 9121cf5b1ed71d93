// lpd: running out of memory ends a run with one line and exit status 1, wherever it happens.
//
// An allocation that fails inside an OpenMP parallel region throws std::bad_alloc where no
// handler can catch it, and the program aborted with a core file. The new-handler installed
// here runs at the failing allocation instead, in any thread: it removes the run's
// temporary files (interruption.h), says how much memory the process had reached against
// its limit, and exits with status 1. A std::bad_alloc thrown without it (Eigen's aligned
// allocator) that reaches std::terminate is reported the same way.
#ifndef LPD_IO_OUT_OF_MEMORY_H_
#define LPD_IO_OUT_OF_MEMORY_H_

namespace lpd::io {

// Installs the new-handler (once per process; later calls do nothing).
void InstallOutOfMemoryHandler();

// Removes the run's temporary files, writes the one-line message above and exits with
// status 1: for a std::bad_alloc caught outside a parallel region (Eigen's allocator).
[[noreturn]] void ExitOutOfMemory();

}  // namespace lpd::io

#endif  // LPD_IO_OUT_OF_MEMORY_H_
