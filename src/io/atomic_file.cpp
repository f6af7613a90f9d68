#include "brb/io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <random>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace brb::io {
namespace {

constexpr std::size_t kBufferBytes = std::size_t{1} << 20;
constexpr int kNameAttempts = 100;

[[noreturn]] void throw_errno(int error, const std::string& what) {
  throw std::system_error(error, std::generic_category(), what);
}

/// ".<name>.tmp-<pid>-<random>" in the target's directory: same file system, so rename is
/// atomic; hidden, so directory listings do not show it.
std::filesystem::path temporary_name_for(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  thread_local std::mt19937_64 generator{std::random_device{}()};
  std::string name = ".";
  name += target.filename().string();
  name += ".tmp-";
  name += std::to_string(::getpid());
  name += '-';
  name += std::to_string(counter++);
  name += '-';
  name += std::to_string(generator() % 1000000007u);
  return target.parent_path() / name;
}

} // namespace

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
  if (target_.filename().empty()) {
    throw_errno(EISDIR, target_.string() + ": expected a file name, got a directory");
  }
  for (int attempt = 0; attempt < kNameAttempts; ++attempt) {
    temporary_ = temporary_name_for(target_);
    descriptor_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (descriptor_ >= 0)
      return;
    if (errno != EEXIST)
      break;
  }
  const int error = errno;
  temporary_.clear();
  throw_errno(error, target_.string() + ": cannot create a temporary file next to it");
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : target_(std::move(other.target_)), temporary_(std::exchange(other.temporary_, {})),
      descriptor_(std::exchange(other.descriptor_, -1)), buffer_(std::move(other.buffer_)) {}

AtomicFile::~AtomicFile() {
  discard();
}

void AtomicFile::write(std::string_view text) {
  if (descriptor_ < 0)
    throw std::logic_error("AtomicFile::write after commit");
  buffer_ += text;
  if (buffer_.size() >= kBufferBytes)
    flush_buffer();
}

void AtomicFile::flush_buffer() {
  std::string_view pending = buffer_;
  while (!pending.empty()) {
    const auto written = ::write(descriptor_, pending.data(), pending.size());
    if (written < 0) {
      if (errno == EINTR)
        continue;
      const int error = errno;
      discard();
      throw_errno(error, target_.string() + ": cannot write");
    }
    pending.remove_prefix(static_cast<std::size_t>(written));
  }
  buffer_.clear();
}

void AtomicFile::commit() {
  if (descriptor_ < 0)
    throw std::logic_error("AtomicFile::commit called twice");
  flush_buffer();
  if (::fsync(descriptor_) != 0) {
    const int error = errno;
    discard();
    throw_errno(error, target_.string() + ": cannot flush to disk");
  }
  if (::close(std::exchange(descriptor_, -1)) != 0) {
    const int error = errno;
    discard();
    throw_errno(error, target_.string() + ": cannot close");
  }
  if (::rename(temporary_.c_str(), target_.c_str()) != 0) {
    const int error = errno;
    discard();
    throw_errno(error, target_.string() + ": cannot replace with the new content");
  }
  temporary_.clear();
}

void AtomicFile::discard() noexcept {
  if (descriptor_ >= 0)
    ::close(std::exchange(descriptor_, -1));
  if (!temporary_.empty()) {
    ::unlink(temporary_.c_str());
    temporary_.clear();
  }
}

void write_file_atomically(const std::filesystem::path& target, std::string_view contents) {
  AtomicFile file(target);
  file.write(contents);
  file.commit();
}

} // namespace brb::io
