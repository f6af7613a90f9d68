// Table-driven tests of rejected JSON inputs: a document made invalid in one place and the
// JSON path the error must name.
#pragma once

#include <nlohmann/json.hpp>

#include <functional>
#include <ostream>
#include <string>

namespace brb::test {

struct InvalidJsonCase {
  std::string name;
  std::function<nlohmann::json()> document;
  std::string path; ///< JSON path the error must name
};

inline void PrintTo(const InvalidJsonCase& invalid, std::ostream* out) {
  *out << invalid.name;
}

/// `document` with member `key` set to `value`.
inline nlohmann::json with(nlohmann::json document, const std::string& key, nlohmann::json value) {
  document[key] = std::move(value);
  return document;
}

/// `document` without member `key`.
inline nlohmann::json without(nlohmann::json document, const std::string& key) {
  document.erase(key);
  return document;
}

} // namespace brb::test
