#include "experiments/atomic_output_file.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include <unistd.h>

namespace lpd::experiments {

void RefuseExistingOutput(const std::string& path, bool overwrite) {
  if (!overwrite && std::filesystem::exists(path)) {
    throw std::runtime_error("output file " + path +
                             " already exists (pass --overwrite to replace it)");
  }
}

AtomicOutputFile::AtomicOutputFile(const std::string& path, bool overwrite) : path_(path) {
  RefuseExistingOutput(path, overwrite);
  temporary_path_ = path + ".tmp." + std::to_string(::getpid());
  stream_.open(temporary_path_, std::ios::binary | std::ios::trunc);
  if (!stream_) throw std::runtime_error("cannot create output file " + path);
}

AtomicOutputFile::~AtomicOutputFile() {
  if (!committed_) {
    stream_.close();
    std::remove(temporary_path_.c_str());
  }
}

void AtomicOutputFile::Commit() {
  stream_.flush();
  const bool good = stream_.good();
  stream_.close();
  if (!good) throw std::runtime_error("error while writing " + path_);
  if (std::rename(temporary_path_.c_str(), path_.c_str()) != 0) {
    throw std::runtime_error("cannot move the output into place at " + path_);
  }
  committed_ = true;
}

}  // namespace lpd::experiments
