// Fuzz helper: the fuzzer's bytes in a file of this process's own, for readers that take a
// path (state files, sweep configs); removed when the object goes.
#ifndef LPD_TESTS_FUZZ_BYTES_FILE_H_
#define LPD_TESTS_FUZZ_BYTES_FILE_H_

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include <unistd.h>

class BytesFile {
 public:
  BytesFile(const uint8_t* data, size_t size, const char* extension)
      : path_("/tmp/lpd_fuzz_" + std::to_string(::getpid()) + extension) {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  ~BytesFile() { std::remove(path_.c_str()); }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

#endif  // LPD_TESTS_FUZZ_BYTES_FILE_H_
