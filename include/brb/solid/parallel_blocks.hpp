// The 3D model's loops on threads (elements of a part, slave nodes of a contact): the range
// [0, n) is cut into `threads` contiguous blocks, each run on its own std::jthread (the first
// on the calling thread); every item writes only its own slots, and the caller sums them in
// item order afterwards, so results are bitwise the same for every thread count.
#pragma once

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace brb::solid {

/// Calls block(begin, end) over contiguous blocks covering [0, n) on min(threads, n) threads
/// and returns when all are done.
template <class Block> void parallel_blocks(std::size_t n, int threads, const Block& block) {
  const std::size_t used = std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), n);
  if (used <= 1) {
    block(std::size_t{0}, n);
    return;
  }
  std::vector<std::jthread> pool;
  pool.reserve(used - 1);
  for (std::size_t t = 1; t < used; ++t)
    pool.emplace_back(block, n * t / used, n * (t + 1) / used);
  block(std::size_t{0}, n / used);
} // the pool joins here

} // namespace brb::solid
