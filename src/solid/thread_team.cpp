#include "brb/solid/thread_team.hpp"

#include <algorithm>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace brb::solid {

// The threads beyond the caller, each waiting for the next loop (a generation count under a
// mutex: every worker runs each loop once, its block or nothing when the loop has fewer
// blocks than threads), then counting itself done. (A busy wait before sleeping was tried
// and measured slower on the 2-core machine: the spinning thread takes the core the caller's
// serial part of the step needs.)
class ThreadTeam::Pool {
public:
  explicit Pool(int workers) {
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
      pending_ = threads_.size();
      std::fill(errors_.begin(), errors_.end(), nullptr);
      ++generation_;
    }
    start_.notify_all();
    std::exception_ptr first;
    try {
      call(block, 0, n / used);
    } catch (...) {
      first = std::current_exception();
    }
    std::unique_lock lock(mutex_);
    done_.wait(lock, [this] { return pending_ == 0; });
    for (const std::exception_ptr& error : errors_) {
      if (!first && error)
        first = error;
    }
    lock.unlock();
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
    std::unique_lock lock(mutex_);
    for (;;) {
      start_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_)
        return;
      seen = generation_;
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
      lock.lock();
      errors_[index - 1] = error;
      if (--pending_ == 0)
        done_.notify_one();
    }
  }

  std::mutex mutex_;
  std::condition_variable start_;
  std::condition_variable done_;
  std::uint64_t generation_ = 0;
  std::size_t pending_ = 0;
  bool stopping_ = false;
  Task task_;
  std::vector<std::exception_ptr> errors_; // per worker, in block order
  std::vector<std::jthread> threads_;      // last: they stop and join before the rest goes
};

ThreadTeam::ThreadTeam(int threads) : threads_(threads) {
  if (threads < 1)
    throw std::invalid_argument("threads must be >= 1 (got " + std::to_string(threads) + ")");
}

ThreadTeam::ThreadTeam(const ThreadTeam& other) : threads_(other.threads_) {}

ThreadTeam& ThreadTeam::operator=(const ThreadTeam& other) {
  if (this != &other) {
    pool_.reset();
    threads_ = other.threads_;
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
    pool_ = std::make_unique<Pool>(threads_ - 1);
  pool_->run(n, used, call, block);
}

} // namespace brb::solid
