#include "io/json.h"

#include <cmath>
#include <cstdio>

namespace lpd::io {

std::string JsonString(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof(escaped), "\\u%04x", c);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string JsonNumber(double value) {
  if (!std::isfinite(value)) return "null";
  char text[32];
  std::snprintf(text, sizeof(text), "%.17g", value);
  return text;
}

std::string JsonObject(const std::vector<std::pair<std::string, std::string>>& members) {
  std::string json = "{";
  for (size_t m = 0; m < members.size(); ++m) {
    json += (m ? ", " : "") + JsonString(members[m].first) + ": " + members[m].second;
  }
  return json + "}";
}

std::string JsonArray(const std::vector<std::string>& values) {
  std::string json = "[";
  for (size_t v = 0; v < values.size(); ++v) json += (v ? ", " : "") + values[v];
  return json + "]";
}

}  // namespace lpd::io
