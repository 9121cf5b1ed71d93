// lpd: JSON text for the records and summaries lpd writes (no reader: sweeps read their
// records back through yaml-cpp, of whose flow style these records are a subset).
#ifndef LPD_IO_JSON_H_
#define LPD_IO_JSON_H_

#include <string>
#include <utility>
#include <vector>

namespace lpd::io {

// `text` as a JSON string literal, quotes included.
std::string JsonString(const std::string& text);

// A JSON number for `value` (17 significant digits, so that it reads back exactly); null
// for NaN and infinities, which JSON cannot hold.
std::string JsonNumber(double value);

// An object from (key, JSON value text) pairs, in order: {"a": 1, "b": "x"}.
std::string JsonObject(const std::vector<std::pair<std::string, std::string>>& members);

// An array from JSON value texts: [1, 2].
std::string JsonArray(const std::vector<std::string>& values);

}  // namespace lpd::io

#endif  // LPD_IO_JSON_H_
