// Table-driven tests of rejected JSON inputs: a document made invalid in one place and the
// JSON path the error must name.
#pragma once

#include "brb/io/input_error.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

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

/// Reads `file` (written from `invalid.document()`) with `read` and checks that it is rejected
/// with an InputError naming the file and the case's JSON path.
template <class Read>
void expect_rejected_at_path(const std::filesystem::path& file, const InvalidJsonCase& invalid,
                             Read&& read) {
  try {
    read();
    FAIL() << invalid.name << " was accepted";
  } catch (const io::InputError& error) {
    EXPECT_EQ(error.file(), file.string());
    EXPECT_EQ(error.location(), invalid.path);
    const std::string message = error.what();
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    EXPECT_NE(message.find(invalid.path), std::string::npos) << message;
    EXPECT_FALSE(error.expected().empty());
  }
}

} // namespace brb::test
