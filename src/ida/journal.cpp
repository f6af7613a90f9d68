#include "brb/ida/journal.hpp"

#include <cerrno>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace brb::ida {
namespace {

[[noreturn]] void fail(const std::filesystem::path& file, const char* what) {
  throw std::system_error(errno, std::generic_category(), file.string() + ": " + what);
}

void write_all(int descriptor, const std::string& text, const std::filesystem::path& file) {
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(descriptor, text.data() + written, text.size() - written);
    if (n < 0) {
      if (errno == EINTR)
        continue;
      fail(file, "cannot write the journal");
    }
    written += static_cast<std::size_t>(n);
  }
}

/// The path of the first member in which two headers differ ("trace/max_runs"), for the
/// error message.
std::string first_difference(const nlohmann::json& found, const nlohmann::json& expected) {
  if (found.is_object() && expected.is_object()) {
    for (const auto& [key, value] : expected.items()) {
      if (!found.contains(key))
        return key + " (missing)";
      if (found.at(key) != value) {
        const std::string inner = first_difference(found.at(key), value);
        return inner.empty() ? key : key + "/" + inner;
      }
    }
  }
  return "";
}

} // namespace

Journal::Journal(std::filesystem::path file, int descriptor)
    : file_(std::move(file)), descriptor_(descriptor) {}

Journal::Journal(Journal&& other) noexcept
    : file_(std::move(other.file_)), descriptor_(other.descriptor_) {
  other.descriptor_ = -1;
}

Journal::~Journal() {
  if (descriptor_ >= 0)
    ::close(descriptor_);
}

Journal Journal::create(const std::filesystem::path& file, const nlohmann::json& header) {
  const std::filesystem::path temporary = file.string() + ".tmp";
  const int descriptor = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (descriptor < 0)
    fail(temporary, "cannot create the journal");
  write_all(descriptor, header.dump() + "\n", temporary);
  if (::fsync(descriptor) != 0 || ::close(descriptor) != 0)
    fail(temporary, "cannot write the journal");
  std::filesystem::rename(temporary, file);
  const int appending = ::open(file.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (appending < 0)
    fail(file, "cannot open the journal");
  return Journal(file, appending);
}

Journal Journal::resume(const std::filesystem::path& file, const nlohmann::json& header,
                        std::vector<nlohmann::json>& entries) {
  std::string text;
  {
    std::ifstream input(file, std::ios::binary);
    if (!input)
      fail(file, "cannot read the journal");
    std::ostringstream content;
    content << input.rdbuf();
    text = content.str();
  }
  // Only complete lines count: the part after the last '\n' is a torn write.
  const std::size_t complete = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
  std::istringstream lines(text.substr(0, complete));
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    nlohmann::json parsed;
    try {
      parsed = nlohmann::json::parse(line);
    } catch (const nlohmann::json::exception&) {
      throw std::invalid_argument("line " + std::to_string(number) +
                                  " is not a JSON journal entry");
    }
    if (number == 1) {
      if (parsed != header)
        throw std::invalid_argument(
            "the journal was written for other inputs (" + first_difference(parsed, header) +
            " differs): resume with the same model, suite and settings, or use another --out");
      continue;
    }
    entries.push_back(std::move(parsed));
  }
  if (number == 0)
    throw std::invalid_argument("the journal has no header line");
  if (complete < text.size())
    std::filesystem::resize_file(file, complete);
  const int descriptor = ::open(file.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (descriptor < 0)
    fail(file, "cannot open the journal");
  return Journal(file, descriptor);
}

void Journal::append(const nlohmann::json& entry) {
  const std::string line = entry.dump() + "\n";
  const std::lock_guard lock(mutex_);
  // One write(2) of the whole line (O_APPEND): a signal cannot leave part of it on disk.
  write_all(descriptor_, line, file_);
  if (::fsync(descriptor_) != 0)
    fail(file_, "cannot flush the journal");
}

} // namespace brb::ida
