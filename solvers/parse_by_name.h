// lpd: reading an enumerated option back from the name its printer gives it.
#ifndef LPD_SOLVERS_PARSE_BY_NAME_H_
#define LPD_SOLVERS_PARSE_BY_NAME_H_

#include <string>

namespace lpd::solvers {

// Sets *value to the candidate whose name_of(candidate) equals `name`; false if none does.
template <typename Value, typename Candidates, typename NameOf>
bool ParseByName(const std::string& name, const Candidates& candidates, NameOf name_of,
                 Value* value) {
  for (const Value& candidate : candidates) {
    if (name == name_of(candidate)) {
      *value = candidate;
      return true;
    }
  }
  return false;
}

}  // namespace lpd::solvers

#endif  // LPD_SOLVERS_PARSE_BY_NAME_H_
