// `brb check` end to end: the real binary (BRB_CLI_PATH) on the example that passes
// (validation/aisc/passes, a small brace that runs in seconds) and on bad check files.
#include "cli/run_brb.hpp"
#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using brb::testing::CliRun;
using brb::testing::lines_of;
using brb::testing::read_file;
using brb::testing::run_brb;
using brb::testing::ScratchDirectory;
using brb::testing::shell_quoted;
using nlohmann::json;

namespace fs = std::filesystem;

const fs::path kExamples = fs::path(BRB_SOURCE_DIR) / "validation" / "aisc";

TEST(CheckCli, ThePassingExampleWritesItsThreeFilesAndPasses) {
  const ScratchDirectory scratch;
  const fs::path out = scratch.path() / "out";
  const CliRun run =
      run_brb("check " + shell_quoted((kExamples / "passes" / "check.json").string()) + " --out " +
              shell_quoted(out.string()));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("verdict: PASS"), std::string::npos) << run.out;
  ASSERT_TRUE(fs::exists(out / "check.json"));
  ASSERT_TRUE(fs::exists(out / "check.md"));
  ASSERT_TRUE(fs::exists(out / "hysteresis.csv"));
  const json result = json::parse(read_file(out / "check.json"));
  EXPECT_EQ(result["verdict"], "PASS");
  EXPECT_EQ(result["edition"], "341-16");
  // Delta_bm = 1.5 % x 212.132 mm x cos 45 deg (small displacements) = 2.25 mm.
  EXPECT_NEAR(result["demand"]["design_deformation"].get<double>(),
              0.015 * 212.132 * std::sqrt(0.5), 1e-9);
  // Delta_by = fy L / E = 275 x 300 / 210000 (no end zones).
  EXPECT_NEAR(result["brace_properties"]["yield_deformation"].get<double>(),
              275.0 * 300.0 / 210000.0, 1e-9);
  // Every cycle's row, the sequence's first ten cycles at the K3.4c amplitudes.
  const json& cycles = result["cycles"];
  ASSERT_GE(cycles.size(), 10U);
  const double dy = 275.0 * 300.0 / 210000.0;
  const double dbm = result["demand"]["design_deformation"].get<double>();
  const std::vector<double> amplitudes{dy,  dy,        0.5 * dbm, 0.5 * dbm, dbm,
                                       dbm, 1.5 * dbm, 1.5 * dbm, 2 * dbm,   2 * dbm};
  for (std::size_t c = 0; c < amplitudes.size(); ++c)
    EXPECT_NEAR(cycles[c]["amplitude"].get<double>(), amplitudes[c], 1e-9) << c;
  for (std::size_t c = 10; c < cycles.size(); ++c)
    EXPECT_NEAR(cycles[c]["amplitude"].get<double>(), 1.5 * dbm, 1e-9) << c;
  // The last cycle reached 200 Delta_by and the one before did not (the loop stops there).
  EXPECT_GE(cycles.back()["cumulative_inelastic_deformation"].get<double>(), 200.0);
  if (cycles.size() > 10) {
    EXPECT_LT(cycles[cycles.size() - 2]["cumulative_inelastic_deformation"].get<double>(), 200.0);
  }
  // Adjusted strengths: omega Ry Pysc with Pysc from the specified Fysc (250 MPa x 160 mm^2).
  const double omega = result["adjusted_strengths"]["omega"].get<double>();
  const double beta = result["adjusted_strengths"]["beta"].get<double>();
  EXPECT_GE(beta, 1.0);
  EXPECT_NEAR(result["adjusted_strengths"]["tension"].get<double>(), omega * 1.1 * 250.0 * 160.0,
              1e-6);
  EXPECT_NEAR(result["adjusted_strengths"]["compression"].get<double>(),
              beta * omega * 1.1 * 250.0 * 160.0, 1e-6);
  // hysteresis.csv: brb cyclic's columns, one row per step plus the initial state.
  const std::vector<std::string> rows = lines_of(read_file(out / "hysteresis.csv"));
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows.front(), "step,cycle,deformation,force,max_lateral_displacement,substeps");
  EXPECT_EQ(static_cast<int>(rows.size()) - 2, result["solver"]["steps"].get<int>());
  const std::string markdown = read_file(out / "check.md");
  EXPECT_NE(markdown.find("**Verdict: PASS**"), std::string::npos);
  EXPECT_NE(markdown.find("| K3.8d beta |"), std::string::npos);
}

TEST(CheckCli, BadCheckFilesExitTwoAndWriteNothing) {
  const ScratchDirectory scratch;
  const std::string brace = (kExamples / "passes" / "brace.json").string();
  const std::string story = "\"story\": {\"height\": 212, \"bay_width\": 212}";
  struct Case {
    std::string text;
    std::string message;
  };
  const std::vector<Case> cases{
      {"{\"brace\": \"" + brace + "\", " + story + ", \"design_drift\": {\"ratio\": -0.01}}",
       "/design_drift/ratio: design story drift ratio must be >= 0"},
      {"{\"brace\": \"" + brace + "\", " + story +
           ", \"design_drift\": {\"ratio\": 0.01}, \"Ry\": 0.5}",
       "/Ry: Ry (expected to specified minimum yield stress) must be >= 1"},
      {"{\"brace\": \"" + brace + "\", " + story +
           ", \"design_drift\": {\"ratio\": 0.01}, \"edition\": \"2016\"}",
       "/edition: unknown edition \"2016\""},
      {"{\"frame\": {\"model\": \"" +
           (fs::path(BRB_SOURCE_DIR) / "frames/brbf3/model.json").string() +
           "\", \"brace\": 7}, \"design_drift\": {\"ratio\": 0.01}}",
       "/frame/brace: brace id 7 is not a brb element of the frame"},
  };
  for (const Case& c : cases) {
    const fs::path file = scratch.write("bad.json", c.text);
    const fs::path out = scratch.path() / "out";
    const CliRun run =
        run_brb("check " + shell_quoted(file.string()) + " --out " + shell_quoted(out.string()));
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_NE(run.err.find("brb: error: " + file.string() + ": " + c.message), std::string::npos)
        << run.err;
    EXPECT_FALSE(fs::exists(out)) << c.text;
  }
}

} // namespace
