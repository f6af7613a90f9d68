// The IDA journal: one JSON line per finished run, appended with a single write(2) and made
// durable with fsync(2) before the run counts as done, so that a process killed at any moment
// leaves every finished run on disk and never half a line (a torn last line, which only a
// crash of the machine could leave, is cut off when the journal is reopened). The first line
// is a header that identifies the inputs; a journal is resumed only for the same inputs.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <mutex>
#include <vector>

namespace brb::ida {

class Journal {
public:
  /// A new journal at `file` whose header line is `header` (written atomically: temporary
  /// file, fsync, rename). Throws std::system_error naming the file.
  static Journal create(const std::filesystem::path& file, const nlohmann::json& header);

  /// Reopens `file` for appending. `entries` receives every complete line after the header
  /// (parsed); a torn last line is cut off. Throws std::invalid_argument when the header is
  /// not `header` (the message says which member differs, e.g. "trace/max_runs") or a
  /// complete line is not JSON; the caller names the file.
  static Journal resume(const std::filesystem::path& file, const nlohmann::json& header,
                        std::vector<nlohmann::json>& entries);

  Journal(Journal&& other) noexcept;
  Journal& operator=(Journal&&) = delete;
  Journal(const Journal&) = delete;
  ~Journal();

  /// Appends one line (thread-safe); returns once it is on disk.
  void append(const nlohmann::json& entry);

  const std::filesystem::path& file() const { return file_; }

private:
  Journal(std::filesystem::path file, int descriptor);
  std::filesystem::path file_;
  int descriptor_ = -1;
  std::mutex mutex_;
};

} // namespace brb::ida
