// Loops on threads: the 3D model's (elements of a part, slave nodes of a contact) and the
// element evaluations of an assembly (model/element_evaluations.hpp). The range
// [0, n) is cut into min(threads, n) contiguous blocks, block t = [n t / used, n (t + 1) / used),
// the first run on the calling thread and the others on a team of threads kept alive between
// calls (an explicit run dispatches a loop every time step: millions of calls, where starting
// and joining threads each time costs as much as a small mesh's work). Every item writes only
// its own slots and the caller sums them in item order afterwards, so results are bitwise the
// same for every thread count.
#pragma once

#include <chrono>
#include <cstddef>
#include <memory>

namespace brb::model {

class ThreadTeam {
public:
  /// A team of `threads` (>= 1; throws std::invalid_argument otherwise). The threads beyond
  /// the caller start on the first loop that needs them. `spin`: how long a thread waiting
  /// for the next loop (a worker), or for the others to finish one (the caller), keeps
  /// polling before it sleeps. Sleeping and waking through the kernel cost some 50 us per
  /// loop (measured on the 2-core machine, 52 us per empty loop of 2 threads), which is a
  /// tenth of an assembly of a 32-element restrained core; polling costs a core while it
  /// lasts, so it pays only when every thread has a core of its own and loops follow each
  /// other closely (the element loop of a Newton solver). 0: sleep at once.
  explicit ThreadTeam(int threads = 1, std::chrono::microseconds spin = {});
  /// Copies take the thread count and spin, not the threads: a copy starts its own team when
  /// it runs.
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
  std::chrono::microseconds spin_{};
  std::unique_ptr<Pool> pool_;
};

} // namespace brb::model
