// lpd: the results of a sweep: one JSON record per cell in results.jsonl (the record of
// truth, appended as cells finish, read back to resume) and the same records as results.csv
// (rewritten atomically after every cell with a fixed column order).
#ifndef LPD_EXPERIMENTS_SWEEP_SWEEP_RESULTS_H_
#define LPD_EXPERIMENTS_SWEEP_SWEEP_RESULTS_H_

#include <mutex>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace lpd::experiments {

// An ordered list of fields. Numbers are stored as text already formatted; non-finite
// numbers become empty text (JSON null, an empty CSV cell).
class ResultRecord {
 public:
  void Add(const std::string& key, const std::string& text);  // a string field
  void Add(const std::string& key, double value);             // a number field
  void Add(const std::string& key, long value);

  const std::vector<std::pair<std::string, std::string>>& fields() const { return fields_; }
  std::string Get(const std::string& key) const;  // "" if absent
  std::string ToJson() const;
  // Parses one line written by ToJson; throws std::runtime_error if it is not one.
  static ResultRecord FromJson(const std::string& line);

 private:
  std::vector<std::pair<std::string, std::string>> fields_;
  std::vector<bool> is_number_;
};

class ResultStore {
 public:
  // Reads the records already in `directory`; the directory is created by the first Append.
  // `csv_columns` fixes the CSV layout.
  ResultStore(const std::string& directory, std::vector<std::string> csv_columns);

  bool Contains(const std::string& cell_id) const;
  // Appends one record (which must have a "cell_id") and rewrites the CSV. Thread-safe.
  void Append(const ResultRecord& record);

  std::string jsonl_path() const { return directory_ + "/results.jsonl"; }
  std::string csv_path() const { return directory_ + "/results.csv"; }
  size_t size() const { return records_.size(); }

 private:
  void WriteCsv() const;

  std::string directory_;
  std::vector<std::string> columns_;
  std::vector<ResultRecord> records_;
  std::set<std::string> done_;
  mutable std::mutex mutex_;
};

}  // namespace lpd::experiments

#endif  // LPD_EXPERIMENTS_SWEEP_SWEEP_RESULTS_H_
