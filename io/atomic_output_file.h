// lpd: an output file that appears only when complete.
//
// Data goes to a temporary file beside the target; Commit() renames it into place. If the
// object is destroyed without Commit() (an error, an exception), the temporary file is
// removed, so a failed run never leaves a half-written output; an interrupted one neither
// (interruption.h). An existing target is refused unless `overwrite` is set. The target "-"
// is standard output: the data is held in a temporary file and copied there on Commit().
#ifndef LPD_IO_ATOMIC_OUTPUT_FILE_H_
#define LPD_IO_ATOMIC_OUTPUT_FILE_H_

#include <fstream>
#include <string>

namespace lpd::io {

// The file name of standard input and output ("-").
inline constexpr const char* kStandardStream = "-";

// Throws std::runtime_error if `path` exists and !overwrite, exists and is not a regular
// file, or its directory is missing or not writable. Commands call it before their work, so
// that a refused output costs nothing; AtomicOutputFile checks again.
void RefuseExistingOutput(const std::string& path, bool overwrite);

class AtomicOutputFile {
 public:
  // Throws std::runtime_error if the target exists (and !overwrite) or cannot be created.
  AtomicOutputFile(const std::string& path, bool overwrite);
  ~AtomicOutputFile();
  AtomicOutputFile(const AtomicOutputFile&) = delete;
  AtomicOutputFile& operator=(const AtomicOutputFile&) = delete;

  std::ofstream& stream() { return stream_; }
  // Flushes, checks for write errors and renames into place; throws on failure.
  void Commit();

 private:
  void CopyToStandardOutput() const;

  std::string path_;
  std::string temporary_path_;
  std::ofstream stream_;
  bool committed_ = false;
  int slot_ = -1;  // in the interruption module's list of temporary files
};

}  // namespace lpd::io

#endif  // LPD_IO_ATOMIC_OUTPUT_FILE_H_
