// Reading JSON input files (comments allowed) so that every error names the file, the JSON
// path (RFC 6901 pointer, e.g. "/chaboche/1/C") and what was expected.
#pragma once

#include "brb/io/input_error.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace brb::io {

/// The whole content of a file; an InputError naming the file when it is missing, not a
/// regular file or unreadable.
std::string read_text_file(const std::filesystem::path& file);

/// Parses JSON text (comments allowed); `source` names it in errors (normally the file name).
nlohmann::json parse_json(std::string_view text, const std::string& source);

/// read_text_file + parse_json, with the file name as written by the user as the source.
nlohmann::json read_json_file(const std::filesystem::path& file);

/// The JSON pointer of member `token` of the value at `parent`: ("/a", "b") -> "/a/b", with
/// '~' and '/' escaped as RFC 6901 requires.
std::string json_pointer_append(std::string_view parent, std::string_view token);

/// A short, human-readable description of a JSON value for error messages, e.g.
/// `a string "abc"`, `an array [1,2]`, `null`, `-5`.
std::string describe_json_value(const nlohmann::json& value);

/// A read-only view of one value of a JSON input file that knows where it is, so that every
/// error it raises names the file and the JSON path. It refers to the document: keep the
/// document alive while views of it are in use.
class JsonValue {
public:
  JsonValue(const nlohmann::json& value, std::string source, std::string path = {})
      : value_(&value), source_(std::move(source)), path_(std::move(path)) {}

  const nlohmann::json& json() const { return *value_; }
  const std::string& source() const { return source_; }
  /// JSON pointer of this value; empty for the document itself.
  const std::string& path() const { return path_; }

  /// An InputError located at this value: `<source>: <path>: <expected>`.
  InputError error(std::string_view expected) const;

  /// Checks that this is an object whose keys are all in `allowed` (in the order listed in
  /// error messages); `what` describes the object for the message when it is not one.
  void expect_object(std::initializer_list<std::string_view> allowed, std::string_view what) const;

  /// The member `key`, or nothing when it is absent (an object is assumed: expect_object first).
  std::optional<JsonValue> find(std::string_view key) const;

  /// The member `key`; when absent, an InputError at its path saying it is required and what
  /// it means (`meaning`, e.g. "yield stress fy, MPa").
  JsonValue at(std::string_view key, std::string_view meaning) const;

  /// Checks that this is an array of at most `max_size` elements and returns its size.
  std::size_t expect_array(std::size_t max_size, std::string_view what) const;

  /// Element `index` of an array (expect_array first).
  JsonValue element(std::size_t index) const;

  /// This value as a finite number; `meaning` says what the number is (e.g. "Young's modulus
  /// E, MPa").
  double number(std::string_view meaning) const;

  /// This value as a string.
  std::string string(std::string_view meaning) const;

private:
  const nlohmann::json* value_;
  std::string source_;
  std::string path_;
};

} // namespace brb::io
