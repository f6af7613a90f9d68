// Output files that are never half-written: the content goes to a temporary file in the
// target's directory, which replaces the target (rename) only once it is complete.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace brb::io {

/// A file being written atomically. Writes go to a fresh temporary file next to `target`;
/// commit() flushes it to disk and renames it onto `target`. Until then `target` (new or
/// pre-existing) is untouched, and if the AtomicFile is destroyed without commit() the
/// temporary file is removed. Errors throw std::system_error naming the file.
class AtomicFile {
public:
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  AtomicFile(AtomicFile&& other) noexcept;
  AtomicFile& operator=(AtomicFile&&) = delete;

  void write(std::string_view text);
  /// Makes the content visible under the target name. Call once.
  void commit();

  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& temporary() const { return temporary_; }

private:
  void flush_buffer();
  void discard() noexcept;

  std::filesystem::path target_;
  std::filesystem::path temporary_;
  int descriptor_ = -1;
  std::string buffer_;
};

/// Writes `contents` to `target` atomically (see AtomicFile).
void write_file_atomically(const std::filesystem::path& target, std::string_view contents);

} // namespace brb::io
