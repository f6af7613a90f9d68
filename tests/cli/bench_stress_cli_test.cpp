// `brb bench stress` (issue 9): a tiny subset of the short suite through the hidden --only
// option, the report files it writes and the exit status; input errors write nothing.
#include "cli/run_brb.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace brb::testing {
namespace {

namespace fs = std::filesystem;

TEST(BenchStressCli, WritesTheReportAndTheCaseTable) {
  const ScratchDirectory scratch;
  const fs::path out = scratch.path() / "stress";
  // Two cheap cases: a truss random history (seed 3) and the truss at 10 x the default step.
  const CliRun run = run_brb("bench stress --seed 3 --out " + shell_quoted(out.string()) +
                             " --only random_history/truss/seed-3,step_size/truss/step-10x");
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("2 cases"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("every case meets the acceptance"), std::string::npos) << run.out;

  const std::vector<std::string> csv = lines_of(read_file(out / "stress_cases.csv"));
  ASSERT_EQ(csv.size(), 3u);
  EXPECT_EQ(csv[0].rfind("name,group,completed,collapsed,nan_count,energy_error,", 0), 0u);
  EXPECT_EQ(csv[1].rfind("random_history/truss/seed-3,random_history,1,0,0,", 0), 0u) << csv[1];
  EXPECT_EQ(csv[2].rfind("step_size/truss/step-10x,step_size,1,0,0,", 0), 0u) << csv[2];
  EXPECT_NE(csv[1].find(",1,\"completed\""), std::string::npos) << csv[1]; // acceptable

  const std::string report = read_file(out / "stress_report.md");
  EXPECT_NE(report.find("# Numerical stress suite (short)"), std::string::npos);
  EXPECT_NE(report.find("`brb bench stress --seed 3 --jobs 1 --only "), std::string::npos);
  EXPECT_NE(report.find("| verdict | **pass** (0 of 2 cases"), std::string::npos) << report;
  EXPECT_NE(report.find("| NaN count | 0 |"), std::string::npos);
  EXPECT_NE(report.find("## random_history"), std::string::npos);
  EXPECT_NE(report.find("## step_size"), std::string::npos);
  EXPECT_EQ(report.find("## frame_collapse"), std::string::npos); // not run
  // nothing else is left in DIR (atomic writes leave no temporary files)
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(out))
    ++files;
  EXPECT_EQ(files, 2);
}

TEST(BenchStressCli, InputErrorsWriteNothing) {
  const ScratchDirectory scratch;
  const fs::path out = scratch.path() / "stress";
  CliRun run = run_brb("bench stress --out " + shell_quoted(out.string()) + " --only no-such-case");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("--only"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out));

  run = run_brb("bench stress --out " + shell_quoted(out.string()) + " --brace " +
                shell_quoted((scratch.path() / "none.json").string()));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("none.json"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out));

  run = run_brb("bench stress --jobs 0");
  EXPECT_EQ(run.exit_code, 2);
  run = run_brb("bench"); // the parent needs a sub-command
  EXPECT_EQ(run.exit_code, 2);
}

} // namespace
} // namespace brb::testing
