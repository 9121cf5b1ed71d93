#include "io/atomic_output_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <fcntl.h>
#include <unistd.h>

#include "io/interruption.h"

namespace lpd::io {
namespace {

namespace fs = std::filesystem;

// Refuses to replace `path` when it exists and !overwrite, or exists and is not a regular file.
void RefuseToReplace(const std::string& path, bool overwrite) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (fs::exists(status)) {
    // A device, directory or pipe is never replaced, not even with overwrite (as root, a
    // rename onto /dev/full would replace the device node).
    if (!fs::is_regular_file(status)) {
      throw std::runtime_error("output " + path + " exists and is not a regular file");
    }
    if (!overwrite) {
      throw std::runtime_error("output file " + path +
                               " already exists (pass --overwrite to replace it)");
    }
  }
}

}  // namespace

void RefuseExistingOutput(const std::string& path, bool overwrite) {
  if (path == kStandardStream) return;
  RefuseToReplace(path, overwrite);
  std::error_code error;
  fs::path directory = fs::path(path).parent_path();
  if (directory.empty()) directory = ".";
  if (!fs::is_directory(directory, error)) {
    throw std::runtime_error("cannot write " + path + ": directory " + directory.string() +
                             " does not exist");
  }
  // Creating a file is the only test that also holds for root and read-only file systems.
  const std::string probe = (directory / (".lpd_probe." + std::to_string(::getpid()))).string();
  const int descriptor = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (descriptor < 0) {
    throw std::runtime_error("cannot write " + path + ": directory " + directory.string() +
                             " is not writable (" + std::strerror(errno) + ")");
  }
  ::close(descriptor);
  ::unlink(probe.c_str());
}

AtomicOutputFile::AtomicOutputFile(const std::string& path, bool overwrite) : path_(path) {
  if (path == kStandardStream) {
    // Held in a temporary file until complete, so that a failed run writes nothing.
    temporary_path_ =
        (fs::temp_directory_path() / ("lpd-stdout." + std::to_string(::getpid()))).string();
  } else {
    RefuseToReplace(path, overwrite);  // creating the temporary file tests the directory
    temporary_path_ = path + ".tmp." + std::to_string(::getpid());
  }
  slot_ = RegisterTemporaryFile(temporary_path_);
  stream_.open(temporary_path_, std::ios::binary | std::ios::trunc);
  if (!stream_) {
    UnregisterTemporaryFile(slot_);
    throw std::runtime_error("cannot create output file " + path + ": " +
                             std::strerror(errno));
  }
}

AtomicOutputFile::~AtomicOutputFile() {
  if (!committed_) {
    stream_.close();
    std::remove(temporary_path_.c_str());
  }
  UnregisterTemporaryFile(slot_);
}

void AtomicOutputFile::Commit() {
  stream_.flush();
  const bool good = stream_.good();
  stream_.close();
  if (!good) {
    throw std::runtime_error("error while writing " + path_ +
                             " (disk full or device error); nothing was written");
  }
  if (path_ == kStandardStream) {
    CopyToStandardOutput();
    return;  // not committed: the destructor removes the temporary file
  }
  if (std::rename(temporary_path_.c_str(), path_.c_str()) != 0) {
    throw std::runtime_error("cannot move the output into place at " + path_);
  }
  committed_ = true;
}

void AtomicOutputFile::CopyToStandardOutput() const {
  std::FILE* file = std::fopen(temporary_path_.c_str(), "rb");
  if (!file) throw std::runtime_error("cannot reopen the output held for standard output");
  char buffer[1 << 16];
  size_t count;
  bool good = true;
  while ((count = std::fread(buffer, 1, sizeof(buffer), file)) > 0) {
    good = good && std::fwrite(buffer, 1, count, stdout) == count;
  }
  std::fclose(file);
  if (!good || std::fflush(stdout) != 0) {
    throw std::runtime_error("error while writing to standard output");
  }
}

}  // namespace lpd::io
