// The IDA journal: header check, durable appends, torn last line cut off on resume.
#include "brb/ida/journal.hpp"

#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <thread>

namespace brb::ida {
namespace {

using testing::ScratchDirectory;

const nlohmann::json kHeader = {{"journal", "brb ida"}, {"model_digest", "0123"}, {"period", 0.5}};

TEST(Journal, AppendedLinesComeBackOnResume) {
  const ScratchDirectory scratch;
  const auto file = scratch.path() / "journal.jsonl";
  {
    Journal journal = Journal::create(file, kHeader);
    journal.append({{"record", 0}, {"intensity", 0.1 + 0.2}});
    journal.append({{"record", 1}, {"intensity", 1.0 / 3.0}});
  }
  std::vector<nlohmann::json> entries;
  Journal journal = Journal::resume(file, kHeader, entries);
  ASSERT_EQ(entries.size(), 2u);
  // doubles round-trip bitwise through the JSON text
  EXPECT_EQ(entries[0]["intensity"].get<double>(), 0.1 + 0.2);
  EXPECT_EQ(entries[1]["intensity"].get<double>(), 1.0 / 3.0);
  journal.append({{"record", 2}});
  entries.clear();
  Journal::resume(file, kHeader, entries);
  EXPECT_EQ(entries.size(), 3u);
}

TEST(Journal, TornLastLineIsCutOff) {
  const ScratchDirectory scratch;
  const auto file = scratch.path() / "journal.jsonl";
  {
    Journal journal = Journal::create(file, kHeader);
    journal.append({{"record", 0}});
  }
  {
    std::ofstream torn(file, std::ios::app | std::ios::binary);
    torn << R"({"record": 1, "inten)"; // a write cut short (no '\n')
  }
  std::vector<nlohmann::json> entries;
  {
    Journal journal = Journal::resume(file, kHeader, entries);
    journal.append({{"record", 5}});
  }
  ASSERT_EQ(entries.size(), 1u);
  entries.clear();
  Journal::resume(file, kHeader, entries);
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[1]["record"], 5);
}

TEST(Journal, OtherInputsAreRefusedNamingWhatDiffers) {
  const ScratchDirectory scratch;
  const auto file = scratch.path() / "journal.jsonl";
  Journal::create(file, kHeader);
  nlohmann::json other = kHeader;
  other["period"] = 0.6;
  std::vector<nlohmann::json> entries;
  try {
    Journal::resume(file, other, entries);
    FAIL() << "a journal of other inputs was resumed";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("(period differs)"), std::string::npos)
        << error.what();
  }
}

TEST(Journal, ConcurrentAppendsKeepWholeLines) {
  const ScratchDirectory scratch;
  const auto file = scratch.path() / "journal.jsonl";
  {
    Journal journal = Journal::create(file, kHeader);
    std::vector<std::jthread> writers;
    for (int t = 0; t < 4; ++t)
      writers.emplace_back([&journal, t] {
        for (int k = 0; k < 25; ++k)
          journal.append({{"thread", t}, {"k", k}, {"padding", std::string(200, 'x')}});
      });
  }
  std::vector<nlohmann::json> entries;
  Journal::resume(file, kHeader, entries);
  EXPECT_EQ(entries.size(), 100u);
}

} // namespace
} // namespace brb::ida
