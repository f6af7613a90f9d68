// `brb bench skips` and `brb bench scaling` end to end on tiny configurations (a few seconds
// each): the report and the CSV are written, with their columns and one row per skip and scene
// (per point); input errors exit with 2 and write nothing. The tests do not look at the times.
#include "cli/run_brb.hpp"
#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace {

using brb::testing::lines_of;
using brb::testing::read_file;
using brb::testing::run_brb;
using brb::testing::ScratchDirectory;
using brb::testing::shell_quoted;

namespace fs = std::filesystem;

const fs::path kSource = BRB_SOURCE_DIR;
const fs::path kRecord =
    fs::path(BRB_SHARED_DIR) / "data" / "ground_motions" / "RSN77_SFERN_PUL164.AT2";

std::string common_inputs(const std::string& frame_option = "--frame") {
  return frame_option + " " + shell_quoted((kSource / "frames/brbf3/model.json").string()) +
         " --record " + shell_quoted(kRecord.string());
}

TEST(BenchCli, SkipsWritesReportAndCsv) {
  const ScratchDirectory scratch;
  const fs::path out = scratch.path() / "skips";
  const auto run = run_brb(
      "bench skips --brace " +
      shell_quoted((kSource / "examples/braces/girona_D3_restrained.json").string()) +
      " --core-elements 2 --amplitudes 0.5 --max-step 0.25 --frame-core-elements 2 --window "
      "0.01 --repeats 1 " +
      common_inputs() + " --out " + shell_quoted(out.string()));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ASSERT_TRUE(fs::exists(out / "SKIPS.md"));
  const std::vector<std::string> lines = lines_of(read_file(out / "skips.csv"));
  ASSERT_EQ(lines.size(), 1u + 5u * 2u); // header + 5 skips x 2 scenes
  EXPECT_EQ(lines[0], "skip,scene,exact,applies,time_on_s,time_off_s,saved_fraction,"
                      "relative_error,identical,hits");
  for (const char* skip :
       {"open_links", "elastic_fast_path", "reuse_tangents", "requested_recorders", "auto"}) {
    int rows = 0;
    for (const std::string& line : lines)
      rows += line.rfind(std::string(skip) + ",", 0) == 0;
    EXPECT_EQ(rows, 2) << skip;
  }
  // the exact skips are identical (column 9) on both scenes
  for (const std::string& line : lines) {
    if (line.rfind("open_links,", 0) == 0 || line.rfind("elastic_fast_path,", 0) == 0 ||
        line.rfind("requested_recorders,", 0) == 0) {
      std::vector<std::string> fields;
      std::string field;
      for (const char c : line + ",") {
        if (c == ',') {
          fields.push_back(field);
          field.clear();
        } else {
          field += c;
        }
      }
      ASSERT_EQ(fields.size(), 10u) << line;
      EXPECT_EQ(fields[7], "0") << line; // relative error
      EXPECT_EQ(fields[8], "1") << line; // identical
    }
  }
  EXPECT_NE(read_file(out / "SKIPS.md").find("| skip | scene |"), std::string::npos);
}

TEST(BenchCli, ScalingWritesReportAndCsv) {
  const ScratchDirectory scratch;
  const fs::path out = scratch.path() / "scaling";
  const auto run =
      run_brb("bench scaling " + common_inputs() +
              " --braces 1 2 --series-length 0.05 --lengths 0.05 0.1 --length-braces 1 "
              "--repeats 1 --out " +
              shell_quoted(out.string()));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ASSERT_TRUE(fs::exists(out / "SCALING.md"));
  const std::vector<std::string> lines = lines_of(read_file(out / "scaling.csv"));
  ASSERT_EQ(lines.size(), 1u + 2u + 2u);
  EXPECT_EQ(lines[0], "series,braces,record_length_s,steps,equations,cpu_s,peak_drift");
  EXPECT_EQ(lines[1].rfind("braces,1,", 0), 0u);
  EXPECT_EQ(lines[2].rfind("braces,2,", 0), 0u);
  EXPECT_EQ(lines[3].rfind("record_length,1,", 0), 0u);
  const std::string report = read_file(out / "SCALING.md");
  EXPECT_NE(report.find("exponent b"), std::string::npos);
}

TEST(BenchCli, MissingInputIsAnInputError) {
  const ScratchDirectory scratch;
  const fs::path out = scratch.path() / "never";
  const auto run =
      run_brb("bench scaling --frame " + shell_quoted((scratch.path() / "absent.json").string()) +
              " --out " + shell_quoted(out.string()));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("absent.json"), std::string::npos);
  EXPECT_FALSE(fs::exists(out));
  const auto one_point = run_brb("bench scaling " + common_inputs() + " --braces 4 --out " +
                                 shell_quoted(out.string()));
  EXPECT_EQ(one_point.exit_code, 2);
  EXPECT_NE(one_point.err.find("--braces"), std::string::npos);
}

} // namespace
