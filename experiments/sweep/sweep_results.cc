#include "experiments/sweep/sweep_results.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "io/atomic_output_file.h"
#include "io/json.h"

namespace lpd::experiments {
namespace {

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

void ResultRecord::Add(const std::string& key, const std::string& text) {
  fields_.emplace_back(key, text);
  is_number_.push_back(false);
}

void ResultRecord::Add(const std::string& key, double value) {
  char text[32] = "";
  if (std::isfinite(value)) std::snprintf(text, sizeof(text), "%.10g", value);
  fields_.emplace_back(key, text);
  is_number_.push_back(true);
}

void ResultRecord::Add(const std::string& key, long value) {
  fields_.emplace_back(key, std::to_string(value));
  is_number_.push_back(true);
}

std::string ResultRecord::Get(const std::string& key) const {
  for (const auto& [name, text] : fields_) {
    if (name == key) return text;
  }
  return "";
}

std::string ResultRecord::ToJson() const {
  std::string json = "{";
  for (size_t f = 0; f < fields_.size(); ++f) {
    const auto& [key, text] = fields_[f];
    json += (f ? ", " : "") + io::JsonString(key) + ": ";
    json += is_number_[f] ? (text.empty() ? "null" : text) : io::JsonString(text);
  }
  return json + "}";
}

ResultRecord ResultRecord::FromJson(const std::string& line) {
  YAML::Node node;
  try {
    node = YAML::Load(line);  // JSON is (for these records) a subset of YAML's flow style
  } catch (const YAML::Exception& error) {
    throw std::runtime_error("not a JSON record: " + error.msg);
  }
  if (!node.IsMap()) throw std::runtime_error("not a JSON object");
  ResultRecord record;
  for (const auto& item : node) {
    const std::string key = item.first.as<std::string>();
    if (item.second.IsNull()) {
      record.Add(key, NAN);
    } else if (item.second.Tag() == "!") {  // a quoted scalar
      record.Add(key, item.second.Scalar());
    } else {
      record.fields_.emplace_back(key, item.second.Scalar());
      record.is_number_.push_back(true);
    }
  }
  return record;
}

ResultStore::ResultStore(const std::string& directory, std::vector<std::string> csv_columns)
    : directory_(directory), columns_(std::move(csv_columns)) {
  std::ifstream in(jsonl_path(), std::ios::binary);
  std::string line;
  long number = 0;
  std::streamoff whole_lines = 0;  // bytes up to the end of the last good record
  bool torn = false;
  while (std::getline(in, line)) {
    ++number;
    const bool ends_with_newline = !in.eof();
    if (line.empty()) {
      whole_lines = in.tellg();
      continue;
    }
    ResultRecord record;
    try {
      record = ResultRecord::FromJson(line);
      if (!ends_with_newline) throw std::runtime_error("no line end");
    } catch (const std::runtime_error& reason) {
      if (in.peek() != EOF) {
        throw std::runtime_error(jsonl_path() + ":" + std::to_string(number) + ": " +
                                 reason.what());
      }
      torn = true;  // a last record cut short (a full disk, a killed run): dropped below
      break;
    }
    const std::string id = record.Get("cell_id");
    if (id.empty()) {
      throw std::runtime_error(jsonl_path() + ":" + std::to_string(number) + ": no cell_id");
    }
    if (done_.insert(id).second) records_.push_back(std::move(record));
    whole_lines = in.eof() ? whole_lines : static_cast<std::streamoff>(in.tellg());
  }
  if (torn) {
    in.close();
    std::error_code error;
    std::filesystem::resize_file(jsonl_path(), static_cast<uintmax_t>(whole_lines), error);
    if (error) {
      throw std::runtime_error(jsonl_path() + ":" + std::to_string(number) +
                               ": a record cut short that cannot be removed: " + error.message());
    }
    std::fprintf(stderr,
                 "warning: %s:%ld: dropped a record cut short by an earlier run; its cell runs "
                 "again\n",
                 jsonl_path().c_str(), number);
  }
}

bool ResultStore::Contains(const std::string& cell_id) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return done_.count(cell_id) > 0;
}

void ResultStore::Append(const ResultRecord& record) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::error_code error;
  std::filesystem::create_directories(directory_, error);
  if (error) throw std::runtime_error(directory_ + ": cannot create directory: " + error.message());
  {
    // Whole or not at all: a record that cannot be written completely is cut off again.
    std::error_code size_error;
    const uintmax_t size = std::filesystem::exists(jsonl_path())
                               ? std::filesystem::file_size(jsonl_path(), size_error)
                               : 0;
    std::ofstream out(jsonl_path(), std::ios::app | std::ios::binary);
    const std::string text = record.ToJson() + "\n";
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.flush();
    if (!out) {
      out.close();
      std::error_code error;
      if (!size_error) std::filesystem::resize_file(jsonl_path(), size, error);
      throw std::runtime_error(jsonl_path() + ": cannot append a record (disk full?)");
    }
  }
  done_.insert(record.Get("cell_id"));
  records_.push_back(record);
  WriteCsv();
}

void ResultStore::WriteCsv() const {
  io::AtomicOutputFile file(csv_path(), /*overwrite=*/true);
  std::ofstream& out = file.stream();
  for (size_t c = 0; c < columns_.size(); ++c) out << (c ? "," : "") << columns_[c];
  out << "\n";
  for (const ResultRecord& record : records_) {
    for (size_t c = 0; c < columns_.size(); ++c) {
      out << (c ? "," : "") << CsvField(record.Get(columns_[c]));
    }
    out << "\n";
  }
  file.Commit();
}

}  // namespace lpd::experiments
