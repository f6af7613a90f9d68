#include "brb/model/thread_team.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace brb::model {

namespace {

/// Polls `done` until it holds or `spin` has passed; whether it held.
template <class Done> bool poll_for(std::chrono::microseconds spin, const Done& done) {
  if (spin.count() <= 0)
    return done();
  const auto until = std::chrono::steady_clock::now() + spin;
  for (int round = 0;; ++round) {
    if (done())
      return true;
    // the clock is read every 64 polls (a read costs more than a poll)
    if (round % 64 == 63 && std::chrono::steady_clock::now() >= until)
      return false;
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause(); // lets the sibling hardware thread run while this one polls
#endif
  }
}

} // namespace

// The threads beyond the caller, each waiting for the next loop (a generation count, changed
// under a mutex: every worker runs each loop once, its block or nothing when the loop has
// fewer blocks than threads), then counting itself done. Waits poll for `spin` first, then
// sleep on a condition variable. The counts are atomics so that polling needs no lock; a
// sleeper cannot miss its wake-up because the generation changes under the mutex, and the
// worker that counts the last one done takes the mutex before it wakes the caller. (For the 3D
// model's explicit steps a team sleeps at once: polling was measured slower there on the 2-core
// machine, the polling thread taking the core the caller's serial part of the step needs.)
class ThreadTeam::Pool {
public:
  Pool(int workers, std::chrono::microseconds spin) : spin_(spin) {
    errors_.resize(static_cast<std::size_t>(workers));
    for (int w = 0; w < workers; ++w)
      threads_.emplace_back([this, w] { work(static_cast<std::size_t>(w) + 1); });
  }
  Pool(const Pool&) = delete;
  Pool& operator=(const Pool&) = delete;
  ~Pool() {
    {
      const std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    start_.notify_all();
  } // the jthreads join here

  void run(std::size_t n, std::size_t used, BlockCall call, const void* block) {
    {
      const std::lock_guard lock(mutex_);
      task_ = {n, used, call, block};
      std::fill(errors_.begin(), errors_.end(), nullptr);
      pending_.store(threads_.size());
      generation_.fetch_add(1);
    }
    start_.notify_all();
    std::exception_ptr first;
    try {
      call(block, 0, n / used);
    } catch (...) {
      first = std::current_exception();
    }
    const auto all_done = [this] { return pending_.load() == 0; };
    if (!poll_for(spin_, all_done)) {
      std::unique_lock lock(mutex_);
      done_.wait(lock, all_done);
    }
    // (the workers' decrements order their errors_ before the count reached 0)
    for (const std::exception_ptr& error : errors_) {
      if (!first && error)
        first = error;
    }
    if (first)
      std::rethrow_exception(first);
  }

private:
  struct Task {
    std::size_t n = 0;
    std::size_t used = 0;
    BlockCall call = nullptr;
    const void* block = nullptr;
  };

  void work(std::size_t index) {
    std::uint64_t seen = 0;
    for (;;) {
      const auto woken = [&] { return stopping_.load() || generation_.load() != seen; };
      const bool polled = poll_for(spin_, woken);
      std::unique_lock lock(mutex_); // the task is written under the mutex
      if (!polled)
        start_.wait(lock, woken);
      if (stopping_.load())
        return;
      seen = generation_.load();
      const Task task = task_;
      lock.unlock();
      std::exception_ptr error;
      if (index < task.used) {
        try {
          task.call(task.block, task.n * index / task.used, task.n * (index + 1) / task.used);
        } catch (...) {
          error = std::current_exception();
        }
      }
      errors_[index - 1] = error;
      if (pending_.fetch_sub(1) == 1) {
        // under the mutex, so that a caller deciding to sleep sees the 0 or is woken
        const std::lock_guard done_lock(mutex_);
        done_.notify_one();
      }
    }
  }

  std::chrono::microseconds spin_;
  std::mutex mutex_;
  std::condition_variable start_;
  std::condition_variable done_;
  std::atomic<std::uint64_t> generation_ = 0;
  std::atomic<std::size_t> pending_ = 0;
  std::atomic<bool> stopping_ = false;
  Task task_;
  std::vector<std::exception_ptr> errors_; // per worker, in block order
  std::vector<std::jthread> threads_;      // last: they stop and join before the rest goes
};

ThreadTeam::ThreadTeam(int threads, std::chrono::microseconds spin)
    : threads_(threads), spin_(spin) {
  if (threads < 1)
    throw std::invalid_argument("threads must be >= 1 (got " + std::to_string(threads) + ")");
}

ThreadTeam::ThreadTeam(const ThreadTeam& other) : threads_(other.threads_), spin_(other.spin_) {}

ThreadTeam& ThreadTeam::operator=(const ThreadTeam& other) {
  if (this != &other) {
    pool_.reset();
    threads_ = other.threads_;
    spin_ = other.spin_;
  }
  return *this;
}

ThreadTeam::ThreadTeam(ThreadTeam&&) noexcept = default;
ThreadTeam& ThreadTeam::operator=(ThreadTeam&&) noexcept = default;
ThreadTeam::~ThreadTeam() = default;

std::size_t ThreadTeam::blocks_for(std::size_t n) const {
  return std::min<std::size_t>(static_cast<std::size_t>(threads_), n);
}

void ThreadTeam::dispatch(std::size_t n, std::size_t used, BlockCall call, const void* block) {
  if (!pool_)
    pool_ = std::make_unique<Pool>(threads_ - 1, spin_);
  pool_->run(n, used, call, block);
}

} // namespace brb::model
