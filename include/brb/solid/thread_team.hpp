// The 3D model's loops on threads (elements of a part, slave nodes of a contact): the range
// [0, n) is cut into min(threads, n) contiguous blocks, block t = [n t / used, n (t + 1) / used),
// the first run on the calling thread and the others on a team of threads kept alive between
// calls (an explicit run dispatches a loop every time step: millions of calls, where starting
// and joining threads each time costs as much as a small mesh's work). Every item writes only
// its own slots and the caller sums them in item order afterwards, so results are bitwise the
// same for every thread count.
#pragma once

#include <cstddef>
#include <memory>

namespace brb::solid {

class ThreadTeam {
public:
  /// A team of `threads` (>= 1; throws std::invalid_argument otherwise). The threads beyond
  /// the caller start on the first loop that needs them.
  explicit ThreadTeam(int threads = 1);
  /// Copies take the thread count, not the threads: a copy starts its own team when it runs.
  ThreadTeam(const ThreadTeam& other);
  ThreadTeam& operator=(const ThreadTeam& other);
  ThreadTeam(ThreadTeam&&) noexcept;
  ThreadTeam& operator=(ThreadTeam&&) noexcept;
  ~ThreadTeam();

  int threads() const { return threads_; }

  /// Calls block(begin, end) over the contiguous blocks covering [0, n) and returns when all
  /// are done. An exception thrown by a block is rethrown here (the first block's in block
  /// order) after every block has finished. Not reentrant: a block must not run the same team.
  template <class Block> void run(std::size_t n, const Block& block) {
    const std::size_t used = blocks_for(n);
    if (used <= 1) {
      block(std::size_t{0}, n);
      return;
    }
    dispatch(n, used, &call_block<Block>, &block);
  }

private:
  using BlockCall = void (*)(const void* block, std::size_t begin, std::size_t end);
  template <class Block>
  static void call_block(const void* block, std::size_t begin, std::size_t end) {
    (*static_cast<const Block*>(block))(begin, end);
  }
  std::size_t blocks_for(std::size_t n) const;
  void dispatch(std::size_t n, std::size_t used, BlockCall call, const void* block);

  class Pool;
  int threads_ = 1;
  std::unique_ptr<Pool> pool_;
};

} // namespace brb::solid
