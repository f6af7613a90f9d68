// The acceptance run of issue 7: the IDA of the 3-storey frame (frames/brbf3) over the ten
// shared records (frames/suites/shared10.json) with the default hunt-and-fill, in CI time.
// Checks what must hold of any correct IDA: every record traced to a collapse bracketed to
// the resolution (or censored at its budget), no NaN, the points consistent with the curves
// and the summary, one run equal to `brb frame --scale` of the same record and scale (an
// independent path through the CLI), and a fragility whose median lies among the capacities.
#include "cli/run_brb.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace brb::testing {
namespace {

namespace fs = std::filesystem;

struct Row {
  std::map<std::string, std::string> cells;
  double number(const std::string& column) const { return std::stod(cells.at(column)); }
};

std::vector<Row> read_csv(const fs::path& file) {
  const std::vector<std::string> lines = lines_of(read_file(file));
  std::vector<std::string> header;
  std::istringstream head(lines.at(0));
  for (std::string cell; std::getline(head, cell, ',');)
    header.push_back(cell);
  std::vector<Row> rows;
  for (std::size_t k = 1; k < lines.size(); ++k) {
    Row row;
    std::istringstream line(lines[k]);
    std::size_t column = 0;
    for (std::string cell; std::getline(line, cell, ','); ++column)
      row.cells[header.at(column)] = cell;
    rows.push_back(row);
  }
  return rows;
}

TEST(IdaBrbf3, TenSharedRecordsTraceToCollapse) {
  const ScratchDirectory scratch;
  const fs::path source(BRB_SOURCE_DIR);
  const fs::path out = scratch.path() / "ida";
  const CliRun run =
      run_brb("ida " + shell_quoted((source / "frames/brbf3/model.json").string()) + " --suite " +
              shell_quoted((source / "frames/suites/shared10.json").string()) +
              " --jobs 2 --quiet --out " + shell_quoted(out.string()));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::cout << run.out;

  const nlohmann::json summary = nlohmann::json::parse(read_file(out / "summary.json"));
  const double resolution = summary["hunt_and_fill"]["resolution"].get<double>();
  const int budget = summary["hunt_and_fill"]["max_runs"].get<int>();
  const std::vector<Row> points = read_csv(out / "ida_points.csv");
  ASSERT_EQ(points.size(), summary["runs"].get<std::size_t>());
  std::map<std::string, std::vector<const Row*>> by_record;
  for (const Row& row : points) {
    for (const auto& [column, cell] : row.cells)
      EXPECT_EQ(cell.find("nan"), std::string::npos) << column << " of " << row.cells.at("record");
    by_record[row.cells.at("record")].push_back(&row);
  }
  ASSERT_EQ(by_record.size(), 10u);
  int collapsed_records = 0;
  for (const nlohmann::json& record : summary["records"]) {
    const auto& runs = by_record.at(record["name"].get<std::string>());
    EXPECT_LE(static_cast<int>(runs.size()), budget);
    double lowest_collapse = INFINITY, highest_survival_below = 0.0;
    for (const Row* row : runs)
      if (row->cells.at("collapse") != "none")
        lowest_collapse = std::min(lowest_collapse, row->number("intensity_g"));
    for (const Row* row : runs) {
      const double intensity = row->number("intensity_g");
      if (row->cells.at("collapse") == "none" && intensity < lowest_collapse)
        highest_survival_below = std::max(highest_survival_below, intensity);
      if (row->cells.at("collapse") == "drift") {
        EXPECT_GT(row->number("max_drift"), summary["drift_limit"].get<double>());
      } else if (row->cells.at("collapse") == "none") {
        EXPECT_LE(row->number("max_drift"), summary["drift_limit"].get<double>());
      }
    }
    if (record["censored"].get<bool>()) {
      EXPECT_TRUE(std::isinf(lowest_collapse)) << record.dump();
      EXPECT_EQ(static_cast<int>(runs.size()), budget) << record.dump();
      continue;
    }
    ++collapsed_records;
    EXPECT_DOUBLE_EQ(record["collapse_intensity_g"].get<double>(), lowest_collapse);
    // resolved to the resolution, unless the budget ran out first (the summary says which)
    const bool resolved = lowest_collapse - highest_survival_below <= resolution + 1e-12;
    EXPECT_EQ(record["bracket_resolved"].get<bool>(), resolved) << record.dump();
    EXPECT_DOUBLE_EQ(record["highest_survival_g"].get<double>(), highest_survival_below);
    if (!resolved) {
      EXPECT_EQ(static_cast<int>(runs.size()), budget) << record.dump();
    }
  }
  EXPECT_GE(collapsed_records, 2) << "the default hunt reaches collapse for most records";

  // one run again through `brb frame` with the same scale: the same peak drifts
  const Row& probe = *by_record.at("elCentro").front();
  const fs::path frame_out = scratch.path() / "frame";
  const CliRun frame = run_brb(
      "frame " + shell_quoted((source / "frames/brbf3/model.json").string()) + " --motion " +
      shell_quoted((fs::path(BRB_SHARED_DIR) / "data/ground_motions/elCentro.AT2").string()) +
      " --scale " + probe.cells.at("scale") + " --out " + shell_quoted(frame_out.string()));
  ASSERT_EQ(frame.exit_code, 0) << frame.err;
  const nlohmann::json frame_summary = nlohmann::json::parse(read_file(frame_out / "summary.json"));
  const std::vector<double> drifts = frame_summary["max_drift"].get<std::vector<double>>();
  ASSERT_EQ(drifts.size(), 3u);
  // `brb frame` multiplies the record by (g x scale), the IDA by g and then by the scale: the
  // ground accelerations differ in the last bit, and the Newton solutions by up to their
  // tolerance, so the drifts agree to 1e-6, not bitwise.
  for (std::size_t s = 0; s < drifts.size(); ++s)
    EXPECT_NEAR(probe.number("drift_" + std::to_string(s + 1)), drifts[s], 1e-6 * drifts[s]);

  ASSERT_FALSE(summary["fragility"].is_null()) << summary.value("fragility_note", "");
  const double median = summary["fragility"]["median_g"].get<double>();
  double smallest = INFINITY, largest = 0.0;
  for (const nlohmann::json& record : summary["records"]) {
    smallest = std::min(smallest, record["collapse_intensity_g"].get<double>());
    largest = std::max(largest, record["collapse_intensity_g"].get<double>());
  }
  EXPECT_GT(median, smallest);
  EXPECT_LT(median, largest * 2.0); // censored records can move it above the largest seen
}

} // namespace
} // namespace brb::testing
