#include "experiments/sweep/method_parameters.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace lpd::experiments {

const std::string* MethodParameters::Given(const std::string& name) {
  known_.insert(name);
  const auto it = method_.parameters.find(name);
  return it == method_.parameters.end() ? nullptr : &it->second.text;
}

void MethodParameters::Fail(const std::string& name, const std::string& reason) const {
  throw std::invalid_argument("parameter " + name + " of method " + method_.method + ": " +
                              reason);
}

int MethodParameters::Integer(const std::string& name, int fallback, int min) {
  int value = fallback;
  if (const std::string* text = Given(name)) {
    char* end = nullptr;
    const long parsed = std::strtol(text->c_str(), &end, 10);
    if (text->empty() || *end != '\0' || parsed < min || parsed > 1000000000L) {
      Fail(name, "'" + *text + "' is not an integer >= " + std::to_string(min));
    }
    value = static_cast<int>(parsed);
  }
  effective_.emplace_back(name, std::to_string(value));
  return value;
}

double MethodParameters::Number(const std::string& name, double fallback, double min,
                                double max) {
  double value = fallback;
  if (const std::string* text = Given(name)) {
    char* end = nullptr;
    value = std::strtod(text->c_str(), &end);
    if (text->empty() || *end != '\0' || !std::isfinite(value) || value < min || value > max) {
      std::ostringstream range;
      range << "'" << *text << "' is not a number in [" << min << ", " << max << "]";
      Fail(name, range.str());
    }
  }
  std::ostringstream out;
  out << value;
  effective_.emplace_back(name, out.str());
  return value;
}

std::string MethodParameters::Choice(const std::string& name, const std::string& fallback,
                                     const std::vector<std::string>& choices) {
  std::string value = fallback;
  if (const std::string* text = Given(name)) {
    if (std::find(choices.begin(), choices.end(), *text) == choices.end()) {
      std::string list;
      for (const std::string& choice : choices) list += (list.empty() ? "" : ", ") + choice;
      Fail(name, "'" + *text + "' is not one of " + list);
    }
    value = *text;
  }
  effective_.emplace_back(name, value);
  return value;
}

std::vector<std::pair<std::string, std::string>> MethodParameters::Finish() const {
  for (const auto& [name, value] : method_.parameters) {
    if (!known_.count(name)) {
      std::string list;
      for (const std::string& known : known_) list += (list.empty() ? "" : ", ") + known;
      throw std::invalid_argument("unknown parameter '" + name + "' of method " +
                                  method_.method + " (known: " + list + ")");
    }
  }
  return effective_;
}

}  // namespace lpd::experiments
