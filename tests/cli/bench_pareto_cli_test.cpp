// `brb bench pareto` end to end: the real binary on tiny matrices (a stocky plate brace through
// one cycle at 2 dy; brbf3 over the first 0.02 s of a record), checking the files it writes,
// their rows, the reference's zero error and that the marked front is the front of the CSV's
// own (time, error) columns (recomputed here with study::pareto_front).
#include "brb/study/pareto_front.hpp"
#include "cli/run_brb.hpp"
#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

using brb::testing::lines_of;
using brb::testing::read_file;
using brb::testing::run_brb;
using brb::testing::ScratchDirectory;
using brb::testing::shell_quoted;
using nlohmann::json;
namespace fs = std::filesystem;

/// A 12 x 10 mm plate, 100 mm long, fixed ends, no casing (stocky: no buckling at 2 dy).
json stocky_brace() {
  return {
      {"name", "stocky plate"},
      {"units", "mm"},
      {"core",
       {{"section", {{"shape", "rectangle"}, {"width", 12.0}, {"depth", 10.0}, {"fibers", {4, 4}}}},
        {"steel",
         {{"E", 210000.0}, {"nu", 0.3}, {"fy", 275.0}, {"H_kin", 21000.0}, {"H_iso", 0.0}}},
        {"yielding_length", 100.0},
        {"elements", 4}}},
      {"ends", "fixed"}};
}

/// CSV cells (no quoted commas in these tests' rows).
std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream stream(line);
  for (std::string cell; std::getline(stream, cell, ',');)
    cells.push_back(cell);
  if (!line.empty() && line.back() == ',')
    cells.emplace_back();
  return cells;
}

struct CsvTable {
  std::map<std::string, std::size_t> column;
  std::vector<std::vector<std::string>> rows;
  const std::string& at(std::size_t row, const std::string& name) const {
    return rows.at(row).at(column.at(name));
  }
};

CsvTable read_csv(const fs::path& file) {
  const std::vector<std::string> lines = lines_of(read_file(file));
  CsvTable table;
  const std::vector<std::string> header = cells_of(lines.at(0));
  for (std::size_t k = 0; k < header.size(); ++k)
    table.column[header[k]] = k;
  for (std::size_t k = 1; k < lines.size(); ++k) {
    table.rows.push_back(cells_of(lines[k]));
    EXPECT_EQ(table.rows.back().size(), header.size()) << lines[k];
  }
  return table;
}

/// The front flags of the CSV agree with the front of its (median time, primary error).
void expect_front_consistent(const CsvTable& table) {
  std::vector<brb::study::TimeErrorPoint> points;
  for (std::size_t r = 0; r < table.rows.size(); ++r)
    points.push_back(
        {std::stod(table.at(r, "median_time_s")), std::stod(table.at(r, "primary_error"))});
  const std::vector<bool> front = brb::study::pareto_front(points);
  bool any = false;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    EXPECT_EQ(table.at(r, "front_primary") == "1", front[r]) << table.at(r, "setting");
    any = any || front[r];
  }
  EXPECT_TRUE(any);
}

TEST(BenchParetoCli, ComponentMatrixWritesTablesAndFront) {
  const ScratchDirectory scratch;
  const fs::path brace = scratch.write("brace.json", stocky_brace().dump());
  // no max_step in the protocol: the settings' max_step (dy) applies
  const fs::path protocol = scratch.write(
      "protocol.json", R"({"units": "dy", "cycles": [{"amplitude": 2, "cycles": 1}]})");
  const json matrix = {
      {"name", "plate"},
      {"kind", "component"},
      {"brace", brace.string()},
      {"protocol", protocol.string()},
      {"repeats", 2},
      {"settings",
       {{{"label", "truss"}, {"fidelity", "truss"}},
        {{"label", "auto"}, {"fidelity", "auto"}},
        {{"label", "full-2"}, {"fidelity", "full"}, {"core_elements", 2}, {"max_step", 0.25}},
        {{"label", "full-4"}, {"fidelity", "full"}, {"core_elements", 4}, {"repeats", 1}}}}};
  const fs::path matrix_file = scratch.write("plate.json", matrix.dump());
  const fs::path out = scratch.path() / "out";
  const auto run = run_brb("bench pareto --matrix " + shell_quoted(matrix_file.string()) +
                           " --out " + shell_quoted(out.string()) + " --jobs 2");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ASSERT_TRUE(fs::is_regular_file(out / "PARETO.md"));
  const CsvTable table = read_csv(out / "pareto.csv");
  ASSERT_EQ(table.rows.size(), 4u);
  EXPECT_EQ(table.at(3, "setting"), "full-4");
  EXPECT_EQ(table.at(3, "reference"), "1");
  EXPECT_EQ(std::stod(table.at(3, "cycle_energy_error")), 0.0);
  EXPECT_EQ(table.at(0, "runs"), "2");
  EXPECT_EQ(table.at(3, "runs"), "1");
  EXPECT_EQ(table.at(1, "built_as"), "full"); // no casing: `auto` builds the full brace
  EXPECT_EQ(table.at(2, "solid_error"), "");  // the matrix names no brb solid run
  for (std::size_t r = 0; r < table.rows.size(); ++r)
    EXPECT_EQ(table.at(r, "status"), "completed");
  expect_front_consistent(table);
  const std::string page = read_file(out / "PARETO.md");
  EXPECT_NE(page.find("Generated by `brb bench pareto --matrix"), std::string::npos);
  EXPECT_NE(page.find("**front**"), std::string::npos);
  EXPECT_NE(page.find("`brb solid`"), std::string::npos);
  EXPECT_NE(page.find("## plate (component)"), std::string::npos);
  EXPECT_NE(run.out.find("wrote"), std::string::npos);
}

TEST(BenchParetoCli, FrameMatrixOverAShortWindow) {
  const ScratchDirectory scratch;
  const json matrix = {
      {"name", "brbf3-short"},
      {"kind", "frame"},
      {"model", BRB_SOURCE_DIR "/frames/brbf3/model.json"},
      {"motion", BRB_SHARED_DIR "/data/ground_motions/elCentro.AT2"},
      {"duration", 0.02},
      {"settings",
       {{{"label", "truss"}, {"fidelity", "truss"}},
        {{"label", "truss-dt"}, {"fidelity", "truss"}, {"dt", 0.0025}},
        {{"label", "full-2"}, {"fidelity", "full"}, {"core_elements", 2}, {"mode", "condensed"}}}}};
  const fs::path matrix_file = scratch.write("brbf3.json", matrix.dump());
  const auto run = run_brb("bench pareto --matrix " + shell_quoted(matrix_file.string()) +
                           " --out " + shell_quoted(scratch.path().string()));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const CsvTable table = read_csv(scratch.path() / "pareto.csv");
  ASSERT_EQ(table.rows.size(), 3u);
  EXPECT_EQ(table.at(2, "reference"), "1");
  EXPECT_EQ(table.at(0, "built_as"), "6 truss; 0 full");
  EXPECT_EQ(table.at(2, "built_as"), "0 truss; 6 full");
  EXPECT_EQ(std::stod(table.at(2, "peak_drift_error")), 0.0);
  EXPECT_FALSE(table.at(0, "residual_drift_error").empty());
  EXPECT_FALSE(table.at(0, "cid_error").empty());
  EXPECT_TRUE(table.at(0, "cycle_energy_error").empty());
  expect_front_consistent(table);
}

TEST(BenchParetoCli, InputErrorsWriteNothing) {
  const ScratchDirectory scratch;
  const fs::path matrix_file =
      scratch.write("bad.json", R"({"name": "x", "kind": "component", "settings": []})");
  const fs::path out = scratch.path() / "out";
  const auto run = run_brb("bench pareto --matrix " + shell_quoted(matrix_file.string()) +
                           " --out " + shell_quoted(out.string()));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("bad.json: /brace: missing required key"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(run_brb("bench pareto --jobs 0").exit_code, 2);
  EXPECT_EQ(run_brb("bench").exit_code, 2);
}

} // namespace
