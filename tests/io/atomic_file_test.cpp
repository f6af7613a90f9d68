// Atomic output: the target holds the old content or the complete new one, never a part, and
// no temporary file is left behind.
#include "brb/io/atomic_file.hpp"
#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <system_error>

namespace brb::io {
namespace {

using testing::read_file;
using testing::ScratchDirectory;

TEST(AtomicFile, WritesTheWholeContent) {
  ScratchDirectory scratch;
  const auto target = scratch.path() / "out.csv";
  write_file_atomically(target, "strain,stress\n0,0\n");
  EXPECT_EQ(read_file(target), "strain,stress\n0,0\n");
  EXPECT_EQ(scratch.entries(), std::vector<std::string>{"out.csv"});
}

TEST(AtomicFile, ReplacesAnExistingFile) {
  ScratchDirectory scratch;
  const auto target = scratch.write("out.csv", "old content that is longer than the new one\n");
  write_file_atomically(target, "new\n");
  EXPECT_EQ(read_file(target), "new\n");
}

TEST(AtomicFile, LargeContentInManyWrites) {
  ScratchDirectory scratch;
  const auto target = scratch.path() / "big.csv";
  std::string expected;
  {
    AtomicFile file(target);
    const std::string line(1000, 'x');
    for (int i = 0; i < 3000; ++i) {
      file.write(line);
      file.write("\n");
      expected += line + "\n";
    }
    EXPECT_FALSE(std::filesystem::exists(target)); // nothing visible before commit
    file.commit();
  }
  EXPECT_EQ(read_file(target), expected);
}

TEST(AtomicFile, AbandonedWriteLeavesNothing) {
  ScratchDirectory scratch;
  const auto target = scratch.path() / "out.csv";
  try {
    AtomicFile file(target);
    file.write("half a ro");
    throw std::runtime_error("the analysis failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_TRUE(scratch.entries().empty());
}

TEST(AtomicFile, AbandonedWriteKeepsThePreviousFile) {
  ScratchDirectory scratch;
  const auto target = scratch.write("out.csv", "previous\n");
  {
    AtomicFile file(target);
    file.write("replacement\n");
  }
  EXPECT_EQ(read_file(target), "previous\n");
  EXPECT_EQ(scratch.entries(), std::vector<std::string>{"out.csv"});
}

TEST(AtomicFile, MissingDirectoryThrowsAndCreatesNothing) {
  ScratchDirectory scratch;
  EXPECT_THROW(write_file_atomically(scratch.path() / "missing" / "out.csv", "x"),
               std::system_error);
  EXPECT_TRUE(scratch.entries().empty());
}

TEST(AtomicFile, TargetThatIsADirectoryThrowsAndLeavesNothing) {
  ScratchDirectory scratch;
  std::filesystem::create_directory(scratch.path() / "out");
  EXPECT_THROW(write_file_atomically(scratch.path() / "out", "x"), std::system_error);
  EXPECT_EQ(scratch.entries(), std::vector<std::string>{"out"});
}

} // namespace
} // namespace brb::io
