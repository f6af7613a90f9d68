// Laboratory force-deformation records: columns by header name, kip/in converted to N/mm,
// excluded row ranges, errors naming the file and place; the reference object of a metrics
// file.
#include "brb/io/force_record.hpp"
#include "brb/io/input_error.hpp"
#include "brb/io/json_input.hpp"
#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace brb::io {
namespace {

// 1 kip = 1000 lbf = 1000 x 0.45359237 kg x 9.80665 m/s^2 (exact definitions of the pound and
// of standard gravity); 1 in = 25.4 mm exactly.
constexpr double kNewtonsPerKip = 1000.0 * 0.45359237 * 9.80665;

ForceRecordFormat kip_inch_format() {
  ForceRecordFormat format;
  format.force_column = "Force[kip]";
  format.deformation_column = "Deformation[in]";
  format.force_unit = "kip";
  format.length_unit = "in";
  return format;
}

TEST(ForceRecord, ConvertsKipAndInchAtTheEdge) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("r.csv", "Force[kip],Deformation[in]\n"
                                           "-4.5,0\n"
                                           "10,0.1\n"
                                           "2,-1\n");
  const ForceRecord record = read_force_record(file, kip_inch_format());
  ASSERT_EQ(record.size(), 3u);
  EXPECT_NEAR(record.force[0], -4.5 * kNewtonsPerKip, 1e-9);
  EXPECT_NEAR(record.force[1], 44482.216152605, 1e-6);
  EXPECT_DOUBLE_EQ(record.deformation[1], 2.54);
  EXPECT_DOUBLE_EQ(record.deformation[2], -25.4);
  EXPECT_EQ(record.row, (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(record.line, (std::vector<std::size_t>{2, 3, 4}));
}

TEST(ForceRecord, ReadsColumnsByNameWhateverTheirOrder) {
  // CB225's record has its deformation column first.
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("r.csv", "Deformation[in],Force[kip]\n"
                                           "0.5,76\n"
                                           "-0.25,-80\n");
  const ForceRecord record = read_force_record(file, kip_inch_format());
  EXPECT_DOUBLE_EQ(record.deformation[0], 12.7);
  EXPECT_NEAR(record.force[0], 76 * kNewtonsPerKip, 1e-9);
  EXPECT_DOUBLE_EQ(record.deformation[1], -6.35);
  EXPECT_NEAR(record.force[1], -80 * kNewtonsPerKip, 1e-9);
}

TEST(ForceRecord, LeavesOutExcludedHalfOpenRowRanges) {
  testing::ScratchDirectory scratch;
  std::string text = "Force[kip],Deformation[in]\n";
  for (int row = 0; row < 10; ++row)
    text += std::to_string(row) + "," + std::to_string(row) + "\n";
  auto format = kip_inch_format();
  format.excluded_rows = {{2, 4}, {7, std::nullopt}};
  const ForceRecord record = read_force_record(scratch.write("r.csv", text), format);
  EXPECT_EQ(record.row, (std::vector<std::size_t>{0, 1, 4, 5, 6}));
  EXPECT_EQ(record.line, (std::vector<std::size_t>{2, 3, 6, 7, 8}));
  EXPECT_DOUBLE_EQ(record.deformation[2], 4 * 25.4);
}

TEST(ForceRecord, ErrorsNameTheFileAndPlace) {
  testing::ScratchDirectory scratch;
  const auto missing_column = scratch.write("a.csv", "Force[kip],Disp[in]\n1,2\n");
  try {
    read_force_record(missing_column, kip_inch_format());
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), missing_column.string());
    EXPECT_NE(error.expected().find("Deformation[in]"), std::string::npos) << error.what();
  }
  const auto bad_cell = scratch.write("b.csv", "Force[kip],Deformation[in]\n1,2\nx,3\n");
  try {
    read_force_record(bad_cell, kip_inch_format());
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "line 3, column Force[kip]") << error.what();
  }
  auto all_excluded = kip_inch_format();
  all_excluded.excluded_rows = {{0, std::nullopt}};
  EXPECT_THROW(
      read_force_record(scratch.write("c.csv", "Force[kip],Deformation[in]\n1,2\n"), all_excluded),
      InputError);
  auto unknown_unit = kip_inch_format();
  unknown_unit.force_unit = "lbf";
  EXPECT_THROW(read_force_record(bad_cell, unknown_unit), InputError);
}

TEST(ForceRecordReference, ResolvesSharedAndRelativePathsAndReadsTheFormat) {
  const auto document = parse_json(R"({"reference": {
      "file": "shared:data/x.csv",
      "columns": {"force": "Force[kip]", "deformation": "Deformation[in]"},
      "units": {"force": "kip", "length": "in"},
      "exclude_rows": [[19475, 20050], [33509, null]]}})",
                                   "m.json");
  const JsonValue root(document, "m.json");
  const ForceRecordReference reference =
      read_force_record_reference(root.at("reference", "record"), "/base", "/work/shared");
  EXPECT_EQ(reference.file, std::filesystem::path("/work/shared/data/x.csv"));
  EXPECT_EQ(reference.format.force_unit, "kip");
  ASSERT_EQ(reference.format.excluded_rows.size(), 2u);
  EXPECT_EQ(reference.format.excluded_rows[0].begin, 19475u);
  EXPECT_EQ(reference.format.excluded_rows[0].end, std::optional<std::size_t>(20050));
  EXPECT_FALSE(reference.format.excluded_rows[1].end.has_value());

  const auto relative = parse_json(R"({"file": "r.csv",
      "columns": {"force": "F", "deformation": "D"}, "units": {"force": "N", "length": "mm"}})",
                                   "m.json");
  EXPECT_EQ(read_force_record_reference(JsonValue(relative, "m.json"), "/base", "/s").file,
            std::filesystem::path("/base/r.csv"));
}

TEST(ForceRecordReference, RejectsBadUnitsAndRangesAtTheirJsonPath) {
  const auto expect_error_at = [](const std::string& text, const std::string& path) {
    const auto document = parse_json(text, "m.json");
    try {
      read_force_record_reference(JsonValue(document, "m.json"), "/b", "/s");
      FAIL() << "expected an InputError for " << text;
    } catch (const InputError& error) {
      EXPECT_EQ(error.location(), path) << error.what();
    }
  };
  const std::string columns = R"("columns": {"force": "F", "deformation": "D"})";
  expect_error_at(R"({"file": "r.csv", )" + columns +
                      R"(, "units": {"force": "lb", "length": "in"}})",
                  "/units/force");
  expect_error_at(R"({"file": "r.csv", )" + columns +
                      R"(, "units": {"force": "kip", "length": "ft"}})",
                  "/units/length");
  expect_error_at(R"({"file": "r.csv", )" + columns +
                      R"(, "units": {"force": "kip", "length": "in"}, "exclude_rows": [[5, 2]]})",
                  "/exclude_rows/0/1");
  expect_error_at(R"({"file": "r.csv", )" + columns +
                      R"(, "units": {"force": "kip", "length": "in"}, "exclude_rows": [[-1, 2]]})",
                  "/exclude_rows/0/0");
  expect_error_at(R"({"file": "r.csv", "units": {"force": "kip", "length": "in"}})", "/columns");
}

TEST(SharedDirectory, IsTheFirstAncestorWithASharedFolder) {
  testing::ScratchDirectory scratch;
  std::filesystem::create_directories(scratch.path() / "shared" / "data");
  std::filesystem::create_directories(scratch.path() / "repo" / "validation" / "PC160");
  EXPECT_EQ(find_shared_directory(scratch.path() / "repo" / "validation" / "PC160"),
            std::optional(scratch.path() / "shared"));
}

} // namespace
} // namespace brb::io
