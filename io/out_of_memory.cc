#include "io/out_of_memory.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>

#include <sys/resource.h>
#include <unistd.h>

#include "io/interruption.h"

namespace lpd::io {

// No allocation from here on: snprintf into a stack buffer, write, _exit.
[[noreturn]] void ExitOutOfMemory() {
  struct rusage usage;
  const long peak_mb = ::getrusage(RUSAGE_SELF, &usage) == 0 ? usage.ru_maxrss / 1024 : -1;
  struct rlimit limit;
  char limit_text[64] = "the machine's memory";
  if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    std::snprintf(limit_text, sizeof(limit_text), "an address-space limit of %lld MB",
                  static_cast<long long>(limit.rlim_cur / (1024 * 1024)));
  }
  char message[512];
  const int length = std::snprintf(
      message, sizeof(message),
      "lpd: error: not enough memory: an allocation failed with %ld MB resident, under %s "
      "(a smaller --max_problem_size or --max_k, or --tile_points, needs less)\n",
      peak_mb, limit_text);
  RemoveTemporaryFiles();
  if (length > 0) {
    [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, message, length);
  }
  ::_exit(1);
}

namespace {

std::terminate_handler default_terminate = nullptr;

// Eigen's aligned allocator throws std::bad_alloc itself, without the new-handler: inside a
// parallel region that ends here.
[[noreturn]] void OnTerminate() {
  if (const std::exception_ptr current = std::current_exception()) {
    try {
      std::rethrow_exception(current);
    } catch (const std::bad_alloc&) {
      ExitOutOfMemory();
    } catch (...) {
    }
  }
  default_terminate();
  std::abort();
}

}  // namespace

void InstallOutOfMemoryHandler() {
  static const bool installed = [] {
    std::set_new_handler(ExitOutOfMemory);
    default_terminate = std::set_terminate(OnTerminate);
    return true;
  }();
  (void)installed;
}

}  // namespace lpd::io
