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
  std::ifstream in(jsonl_path());
  std::string line;
  long number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    ResultRecord record;
    try {
      record = ResultRecord::FromJson(line);
    } catch (const std::runtime_error& reason) {
      if (in.peek() == EOF) break;  // a last line cut short by an interrupted run: redo it
      throw std::runtime_error(jsonl_path() + ":" + std::to_string(number) + ": " + reason.what());
    }
    const std::string id = record.Get("cell_id");
    if (id.empty()) {
      throw std::runtime_error(jsonl_path() + ":" + std::to_string(number) + ": no cell_id");
    }
    if (done_.insert(id).second) records_.push_back(std::move(record));
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
    std::ofstream out(jsonl_path(), std::ios::app);
    out << record.ToJson() << "\n";
    out.flush();
    if (!out) throw std::runtime_error(jsonl_path() + ": cannot append a record");
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
