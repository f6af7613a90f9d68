// ThreadTeam (the loop threads of the 3D model and of the element assembly): every item of [0, n)
// is run exactly once, in the documented contiguous blocks, for any thread and item count, also
// over many consecutive loops on the same team (the threads are kept between loops); a block's
// exception reaches the caller after the loop; copies are independent teams.
#include "brb/model/thread_team.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace brb::model {
namespace {

TEST(ThreadTeam, RunsEveryItemOnceInTheDocumentedBlocks) {
  for (int threads = 1; threads <= 5; ++threads) {
    ThreadTeam team(threads);
    for (std::size_t n = 0; n <= 23; ++n) {
      std::vector<int> visits(n, 0);
      std::vector<std::size_t> block_of(n, 99);
      team.run(n, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
          ++visits[i];
          block_of[i] = begin;
        }
      });
      const std::size_t used = std::min<std::size_t>(static_cast<std::size_t>(threads), n);
      for (std::size_t i = 0; i < n; ++i) {
        EXPECT_EQ(visits[i], 1) << threads << " threads, n " << n << ", item " << i;
        // block t = [n t / used, n (t + 1) / used)
        std::size_t t = 0;
        while (!(i < n * (t + 1) / used))
          ++t;
        EXPECT_EQ(block_of[i], n * t / used) << threads << " threads, n " << n << ", item " << i;
      }
    }
  }
}

// Both ways of waiting: sleeping at once, and polling first (the element loop's teams), where
// a worker may see the next loop's generation while the caller is still between loops.
TEST(ThreadTeam, KeepsItsThreadsOverManyLoopsAndUsesThem) {
  for (const std::chrono::microseconds spin :
       {std::chrono::microseconds(0), std::chrono::microseconds(200)}) {
    ThreadTeam team(3, spin);
    std::vector<long> sums(300, 0);
    std::vector<std::thread::id> runner(3);
    for (int loop = 0; loop < 2000; ++loop) {
      team.run(sums.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
          sums[i] += static_cast<long>(i);
        runner[begin / 100] = std::this_thread::get_id();
      });
      if (loop % 500 == 0) // a pause longer than the polling: the workers sleep and wake
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    for (std::size_t i = 0; i < sums.size(); ++i)
      ASSERT_EQ(sums[i], 2000L * static_cast<long>(i)) << "spin " << spin.count() << " us";
    // the first block runs on the caller, the others on two other threads
    EXPECT_EQ(runner[0], std::this_thread::get_id());
    EXPECT_NE(runner[1], std::this_thread::get_id());
    EXPECT_NE(runner[2], std::this_thread::get_id());
    EXPECT_NE(runner[1], runner[2]);
  }
}

TEST(ThreadTeam, RethrowsTheFirstBlocksExceptionAfterTheLoop) {
  ThreadTeam team(4, std::chrono::microseconds(100));
  std::vector<int> visits(40, 0);
  try {
    team.run(visits.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
        ++visits[i];
      if (begin >= 10)
        throw std::runtime_error("block at " + std::to_string(begin));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "block at 10"); // block order, not the order they failed in
  }
  for (const int count : visits)
    EXPECT_EQ(count, 1); // every block ran to its end before the rethrow
  // the team still works
  long sum = 0;
  team.run(1, [&](std::size_t, std::size_t end) { sum += static_cast<long>(end); });
  EXPECT_EQ(sum, 1);
}

TEST(ThreadTeam, CopiesAreIndependentTeamsAndBadCountsAreRefused) {
  ThreadTeam team(2);
  std::vector<int> visits(10, 0);
  const auto count = [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      ++visits[i];
  };
  team.run(visits.size(), count);
  ThreadTeam copy = team;
  EXPECT_EQ(copy.threads(), 2);
  copy.run(visits.size(), count);
  team.run(visits.size(), count);
  for (const int visit : visits)
    EXPECT_EQ(visit, 3);
  EXPECT_THROW(ThreadTeam(0), std::invalid_argument);
}

} // namespace
} // namespace brb::model
