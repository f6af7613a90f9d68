// The specimen folders' record references read the shared lab records as intended: row
// counts after the exclusions and first values, checked against an independent count of
// the CSV files (Python csv module, raw_trim_ranges.yaml applied as half-open ranges).
#include "brb/io/force_record.hpp"
#include "brb/io/json_input.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace brb::validation {
namespace {

io::ForceRecord read_specimen_record(const std::string& id) {
  const std::filesystem::path metrics =
      std::filesystem::path(BRB_SOURCE_DIR) / "validation" / id / "metrics.json";
  const auto document = io::read_json_file(metrics);
  const io::JsonValue root(document, metrics.string());
  const io::ForceRecordReference reference = io::read_force_record_reference(
      root.at("reference", "record"), metrics.parent_path(), BRB_SHARED_DIR);
  return io::read_force_record(reference.file, reference.format);
}

TEST(LabRecords, SpecimenReferencesReadTheSharedRecords) {
  if (!std::filesystem::is_directory(std::filesystem::path(BRB_SHARED_DIR) / "data" /
                                     "brb_tests")) {
    GTEST_SKIP() << "no shared lab records at " << BRB_SHARED_DIR;
  }
  // PC160: 34,100 rows minus [19475, 20050) and [33509, end): 34100 - 575 - 591.
  const io::ForceRecord pc160 = read_specimen_record("PC160");
  EXPECT_EQ(pc160.size(), 32934u);
  EXPECT_EQ(pc160.row[19475], 20050u);
  // First row: -4.303696 kip, 0 in.
  EXPECT_NEAR(pc160.force[0], -4.303696 * 4448.2216152605, 1e-6);
  // CB225 has its deformation column first: first row -0.033994334 in, 1.227259466 kip.
  const io::ForceRecord cb225 = read_specimen_record("CB225");
  EXPECT_EQ(cb225.size(), 486u);
  EXPECT_NEAR(cb225.deformation[0], -0.033994334 * 25.4, 1e-12);
  EXPECT_NEAR(cb225.force[0], 1.227259466 * 4448.2216152605, 1e-6);
  // PC3SB: 99,649 rows; kept: [0, 26387) + [27010, 34963) + [35340, 51300) = 50300.
  EXPECT_EQ(read_specimen_record("PC3SB").size(), 50300u);
}

} // namespace
} // namespace brb::validation
