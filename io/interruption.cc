#include "io/interruption.h"

#include <atomic>
#include <csignal>
#include <cstring>

#include <unistd.h>

namespace lpd::io {
namespace {

constexpr int kSlots = 64;
constexpr size_t kPathBytes = 4096;

std::atomic<int> pending_signal{0};

// A slot is claimed (state 1) by RegisterTemporaryFile, filled, then published (state 2);
// the signal handlers read published slots only.
std::atomic<int> slot_state[kSlots];
char slot_path[kSlots][kPathBytes];

const char* SignalName(int signal) { return signal == SIGINT ? "SIGINT" : "SIGTERM"; }

// Async-signal-safe: unlink, rmdir, write and _exit only.
[[noreturn]] void RemoveTemporaryFilesAndExit(int signal) {
  RemoveTemporaryFiles();
  static const char kMessage[] = "lpd: interrupted; no output written\n";
  [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, kMessage, sizeof(kMessage) - 1);
  ::_exit(128 + signal);
}

void OnWatchdog(int) { RemoveTemporaryFilesAndExit(pending_signal.load()); }

void OnSignal(int signal) {
  int expected = 0;
  if (!pending_signal.compare_exchange_strong(expected, signal)) {
    RemoveTemporaryFilesAndExit(expected);  // the second signal
  }
  ::alarm(1);
}

}  // namespace

void RemoveTemporaryFiles() {
  for (int s = 0; s < kSlots; ++s) {
    if (slot_state[s].load() == 2) ::unlink(slot_path[s]);
  }
  for (int s = 0; s < kSlots; ++s) {
    if (slot_state[s].load() == 2) ::rmdir(slot_path[s]);
  }
}

void InstallInterruptionHandlers() {
  static const bool installed = [] {
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    sigemptyset(&action.sa_mask);
    action.sa_handler = OnSignal;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    action.sa_handler = OnWatchdog;
    sigaction(SIGALRM, &action, nullptr);
    // A write beyond the file-size limit (ulimit -f) then fails like a full disk, with an
    // error the writer reports, instead of killing the process mid-file.
    std::signal(SIGXFSZ, SIG_IGN);
    return true;
  }();
  (void)installed;
}

int InterruptionSignal() { return pending_signal.load(); }

Interrupted::Interrupted(int signal)
    : std::runtime_error(std::string("interrupted by ") + SignalName(signal) +
                         "; no output written"),
      signal_(signal) {}

void ThrowIfInterrupted() {
  if (const int signal = InterruptionSignal()) throw Interrupted(signal);
}

int RegisterTemporaryFile(const std::string& path) {
  if (path.size() >= kPathBytes) return -1;
  for (int s = 0; s < kSlots; ++s) {
    int expected = 0;
    if (!slot_state[s].compare_exchange_strong(expected, 1)) continue;
    std::memcpy(slot_path[s], path.c_str(), path.size() + 1);
    slot_state[s].store(2);
    return s;
  }
  return -1;
}

void UnregisterTemporaryFile(int slot) {
  if (slot >= 0 && slot < kSlots) slot_state[slot].store(0);
}

}  // namespace lpd::io
