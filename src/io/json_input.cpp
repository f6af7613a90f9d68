#include "brb/io/json_input.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <set>
#include <system_error>
#include <vector>

namespace brb::io {
namespace {

constexpr std::size_t kLongestQuotedValue = 60;

std::string truncated(std::string text) {
  if (text.size() > kLongestQuotedValue) {
    text.resize(kLongestQuotedValue - 3);
    text += "...";
  }
  return text;
}

/// Compact JSON text of a value; invalid UTF-8 is replaced rather than thrown on.
std::string compact_dump(const nlohmann::json& value) {
  return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string join(std::initializer_list<std::string_view> words) {
  std::string joined;
  for (const auto word : words) {
    if (!joined.empty())
      joined += ", ";
    joined += word;
  }
  return joined;
}

/// Rejects an object key given twice (nlohmann::json would silently keep the last value, so
/// a second "fy" further down a file would win unnoticed). Follows the parse events to know
/// the JSON path of the duplicate.
class DuplicateKeyGuard {
public:
  explicit DuplicateKeyGuard(const std::string& source) : source_(source) {}

  void observe(nlohmann::json::parse_event_t event, const nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    switch (event) {
    case Event::object_start:
    case Event::array_start:
      containers_.push_back(Container{.is_array = event == Event::array_start});
      break;
    case Event::key: {
      Container& object = containers_.back();
      object.current_key = parsed.get<std::string>();
      if (!object.keys.insert(object.current_key).second) {
        throw InputError(source_, path_to_current(),
                         "duplicate key: each key may appear only once in an object");
      }
      break;
    }
    case Event::object_end:
    case Event::array_end:
      containers_.pop_back();
      next_element();
      break;
    case Event::value:
      next_element();
      break;
    }
  }

private:
  struct Container {
    bool is_array = false;
    std::size_t index = 0;     ///< arrays: index of the element being read
    std::string current_key{}; ///< objects: key of the member being read
    std::set<std::string> keys{};
  };

  void next_element() {
    if (!containers_.empty() && containers_.back().is_array)
      ++containers_.back().index;
  }

  std::string path_to_current() const {
    std::string path;
    for (const auto& container : containers_) {
      path = json_pointer_append(path, container.is_array ? std::to_string(container.index)
                                                          : container.current_key);
    }
    return path;
  }

  const std::string& source_;
  std::vector<Container> containers_;
};

} // namespace

std::string read_text_file(const std::filesystem::path& file) {
  const std::string source = file.string();
  std::error_code status_error;
  const auto status = std::filesystem::status(file, status_error);
  if (!std::filesystem::exists(status)) {
    throw InputError(source, "", "cannot read the file: it does not exist");
  }
  if (std::filesystem::is_directory(status)) {
    throw InputError(source, "", "cannot read the file: it is a directory");
  }
  std::ifstream stream(file, std::ios::binary);
  if (!stream) {
    throw InputError(source, "", std::string("cannot open the file: ") + std::strerror(errno));
  }
  std::string text{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
  if (stream.bad()) {
    throw InputError(source, "", std::string("cannot read the file: ") + std::strerror(errno));
  }
  return text;
}

nlohmann::json parse_json(std::string_view text, const std::string& source) {
  DuplicateKeyGuard duplicate_keys(source);
  try {
    return nlohmann::json::parse(
        text,
        [&duplicate_keys](int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
          duplicate_keys.observe(event, parsed);
          return true;
        },
        /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const nlohmann::json::exception& error) {
    // Syntax errors and numbers out of double range. what() reads
    // "[json.exception.parse_error.101] parse error at line 3, column 7: ...": the
    // bracketed id means nothing to a user.
    std::string message = error.what();
    if (const auto id_end = message.find("] ");
        message.starts_with("[json.exception.") && id_end != std::string::npos) {
      message.erase(0, id_end + 2);
    }
    throw InputError(source, "", "invalid JSON: " + message);
  }
}

nlohmann::json read_json_file(const std::filesystem::path& file) {
  return parse_json(read_text_file(file), file.string());
}

std::string json_pointer_append(std::string_view parent, std::string_view token) {
  std::string pointer(parent);
  pointer += '/';
  for (const char character : token) {
    if (character == '~') {
      pointer += "~0";
    } else if (character == '/') {
      pointer += "~1";
    } else {
      pointer += character;
    }
  }
  return pointer;
}

std::string describe_json_value(const nlohmann::json& value) {
  switch (value.type()) {
  case nlohmann::json::value_t::null:
    return "null";
  case nlohmann::json::value_t::boolean:
    return value.get<bool>() ? "true" : "false";
  case nlohmann::json::value_t::number_integer:
  case nlohmann::json::value_t::number_unsigned:
  case nlohmann::json::value_t::number_float:
    return compact_dump(value);
  case nlohmann::json::value_t::string:
    return "a string " + truncated(compact_dump(value));
  case nlohmann::json::value_t::array:
    return "an array " + truncated(compact_dump(value));
  case nlohmann::json::value_t::object:
    return "an object " + truncated(compact_dump(value));
  default:
    return "a value of an unsupported kind";
  }
}

InputError JsonValue::error(std::string_view expected) const {
  return InputError(source_, path_.empty() ? "top level" : path_, std::string(expected));
}

void JsonValue::expect_object(std::initializer_list<std::string_view> allowed,
                              std::string_view what) const {
  if (!json().is_object()) {
    throw error("expected " + std::string(what) + ", got " + describe_json_value(json()));
  }
  for (const auto& member : json().items()) {
    const bool known = std::find(allowed.begin(), allowed.end(), member.key()) != allowed.end();
    if (!known) {
      throw InputError(source_, json_pointer_append(path_, member.key()),
                       "unknown key; allowed keys are: " + join(allowed));
    }
  }
}

std::optional<JsonValue> JsonValue::find(std::string_view key) const {
  const auto member = json().find(key);
  if (member == json().end())
    return std::nullopt;
  return JsonValue(*member, source_, json_pointer_append(path_, key));
}

JsonValue JsonValue::at(std::string_view key, std::string_view meaning) const {
  auto member = find(key);
  if (!member) {
    throw InputError(source_, json_pointer_append(path_, key),
                     "missing required key (" + std::string(meaning) + ")");
  }
  return std::move(*member);
}

std::size_t JsonValue::expect_array(std::size_t max_size, std::string_view what) const {
  if (!json().is_array()) {
    throw error("expected an array (" + std::string(what) + "), got " +
                describe_json_value(json()));
  }
  if (json().size() > max_size) {
    throw error("expected at most " + std::to_string(max_size) + " elements (" + std::string(what) +
                "), got " + std::to_string(json().size()));
  }
  return json().size();
}

JsonValue JsonValue::element(std::size_t index) const {
  return JsonValue(json().at(index), source_, json_pointer_append(path_, std::to_string(index)));
}

double JsonValue::number(std::string_view meaning) const {
  if (!json().is_number()) {
    throw error("expected a number (" + std::string(meaning) + "), got " +
                describe_json_value(json()));
  }
  const double value = json().get<double>();
  if (!std::isfinite(value)) {
    throw error("expected a finite number (" + std::string(meaning) + "), got " +
                describe_json_value(json()));
  }
  return value;
}

std::string JsonValue::string(std::string_view meaning) const {
  if (!json().is_string()) {
    throw error("expected a string (" + std::string(meaning) + "), got " +
                describe_json_value(json()));
  }
  return json().get<std::string>();
}

} // namespace brb::io
