// `brb validate` end to end: the real binary (BRB_CLI_PATH) on a validation folder made in a
// temporary directory, with one tiny specimen (a short, stocky bare plate core through one
// cycle at 2 dy) so that each run takes a fraction of a second.
#include "brb/io/csv.hpp"
#include "cli/run_brb.hpp"
#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <sstream>
#include <string>

namespace {

using brb::testing::CliRun;
using brb::testing::read_file;
using brb::testing::run_brb;
using brb::testing::run_brb_until_checkpoint;
using brb::testing::ScratchDirectory;
using brb::testing::shell_quoted;
using nlohmann::json;

namespace fs = std::filesystem;

// The tiny specimen: a 12 x 10 mm S275 plate, 100 mm long, fixed ends, linear kinematic
// hardening 21000 MPa (stocky: it does not buckle at 2 dy). Py = 275 x 120 = 33000 N.
constexpr double kYieldForce = 275.0 * 12.0 * 10.0; // N

json tiny_brace() {
  return {
      {"name", "tiny"},
      {"core",
       {{"section", {{"shape", "rectangle"}, {"width", 12.0}, {"depth", 10.0}, {"fibers", {4, 4}}}},
        {"steel",
         {{"E", 210000.0}, {"nu", 0.3}, {"fy", 275.0}, {"H_kin", 21000.0}, {"H_iso", 0.0}}},
        {"yielding_length", 100.0},
        {"elements", 4}}},
      {"ends", "fixed"}};
}

json tiny_metrics() {
  return {{"id", "tiny"},
          {"title", "a stocky bare plate"},
          {"source", "this test"},
          {"brace", "brace.json"},
          {"protocol", "protocol.json"},
          {"refinements", {1}},
          {"metrics",
           {// Past yield at 2 dy with positive hardening, the peak tension exceeds Py.
            {{"name", "peak tension"},
             {"kind", "peak_force"},
             {"direction", "tension"},
             {"at_least", kYieldForce},
             {"unit", "N"},
             {"source", "hardening: F > Py = fy A past yield"}},
            {{"name", "no global buckling"},
             {"kind", "flag"},
             {"flag", "global_buckling"},
             {"expected", false}},
            {{"name", "loop energy"}, {"kind", "cycle_energy"}, {"cycle", 1}, {"unit", "N mm"}}}}};
}

/// A validation folder with the tiny specimen; `metrics` replaces its metrics.json.
fs::path make_folder(const ScratchDirectory& scratch, const json& metrics = tiny_metrics()) {
  fs::create_directories(scratch.path() / "validation" / "tiny");
  scratch.write("validation/tiny/brace.json", tiny_brace().dump(2));
  scratch.write("validation/tiny/protocol.json",
                R"({"units": "dy", "cycles": [{"amplitude": 2, "cycles": 1}], "max_step": 0.25})");
  scratch.write("validation/tiny/metrics.json", "// comments allowed\n" + metrics.dump(2));
  return scratch.path() / "validation";
}

TEST(ValidateCli, RunsEveryRefinementAndWritesTheReports) {
  const ScratchDirectory scratch;
  const fs::path folder = make_folder(scratch);
  const CliRun run = run_brb("validate " + shell_quoted(folder.string()) + " --refinements 1,2");
  ASSERT_TRUE(run.exit_code == 0 || run.exit_code == 1) << run.err;
  EXPECT_TRUE(run.err.empty()) << run.err;

  const json report = json::parse(read_file(folder / "report.json"));
  // Exit status 0 exactly when every check passed.
  EXPECT_EQ(run.exit_code == 0, report.at("passed").get<bool>()) << run.out;
  const json& runs = report.at("specimens").at(0).at("runs");
  ASSERT_EQ(runs.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const int refinement = static_cast<int>(i) + 1;
    EXPECT_EQ(runs[i].at("refinement"), refinement);
    EXPECT_EQ(runs[i].at("core_elements"), 4 * refinement);
    EXPECT_TRUE(runs[i].at("completed").get<bool>());
    std::string run_folder = "x"; // appended, not "x" + ...: GCC 12 warns falsely (-Wrestrict)
    run_folder += std::to_string(refinement);
    const fs::path outputs = folder / "tiny" / "out" / run_folder;
    EXPECT_TRUE(fs::is_regular_file(outputs / "hysteresis.csv"));
    EXPECT_TRUE(fs::is_regular_file(outputs / "summary.json"));
    const json& checks = runs[i].at("checks");
    // completion, energy balance, integration misfit, then the three metrics
    ASSERT_EQ(checks.size(), 6u);
    EXPECT_EQ(checks[0].at("status"), "pass");
    // The energy balance is judged against 1e-6, whatever the solver gives.
    const double balance = checks[1].at("value").get<double>();
    EXPECT_EQ(checks[1].at("status"), balance <= 1e-6 ? "pass" : "fail");
    EXPECT_EQ(checks[2].at("status"), "reported");
    const json summary = json::parse(read_file(outputs / "summary.json"));
    EXPECT_EQ(checks[2].at("value").get<double>(),
              summary.at("energy_balance").at("relative_misfit").get<double>());
    EXPECT_EQ(checks[3].at("name"), "peak tension");
    EXPECT_EQ(checks[3].at("status"), "pass");
    EXPECT_GT(checks[3].at("value").get<double>(), kYieldForce);
    EXPECT_EQ(checks[4].at("status"), "pass");
    EXPECT_EQ(checks[5].at("status"), "reported");
    // The loop energy is the summary's energy of cycle 1 (same trapezoidal rule).
    EXPECT_NEAR(checks[5].at("value").get<double>(),
                summary.at("cycles").at(0).at("energy").get<double>(),
                1e-9 * summary.at("cycles").at(0).at("energy").get<double>());
  }
  const std::string markdown = read_file(folder / "REPORT.md");
  EXPECT_EQ(markdown.rfind("# Validation report\n\n**", 0), 0u) << markdown;
  EXPECT_NE(markdown.find("### tiny, refinement x2 (8 core elements)"), std::string::npos);
  EXPECT_NE(run.out.find("brb validate: "), std::string::npos) << run.out;
}

TEST(ValidateCli, ReportOptionChoosesWhereBothReportsGo) {
  const ScratchDirectory scratch;
  const fs::path folder = make_folder(scratch);
  const fs::path report = scratch.path() / "tiny-report.md";
  const CliRun run = run_brb("validate " + shell_quoted(folder.string()) +
                             " --only tiny --report " + shell_quoted(report.string()));
  ASSERT_TRUE(run.exit_code == 0 || run.exit_code == 1) << run.err;
  EXPECT_TRUE(fs::is_regular_file(report));
  EXPECT_TRUE(fs::is_regular_file(scratch.path() / "tiny-report.json"));
  EXPECT_FALSE(fs::exists(folder / "REPORT.md"));
}

TEST(ValidateCli, ProgressPrintsALineForEveryStepOfEveryRun) {
  const ScratchDirectory scratch;
  const fs::path folder = make_folder(scratch);
  const CliRun run = run_brb("validate " + shell_quoted(folder.string()) +
                             " --refinements 1,2 --jobs 2 --progress 0");
  ASSERT_TRUE(run.exit_code == 0 || run.exit_code == 1) << run.err;
  const json report = json::parse(read_file(folder / "report.json"));
  const json& runs = report.at("specimens").at(0).at("runs");
  ASSERT_EQ(runs.size(), 2u);
  // --progress 0: one whole line per converged step, labelled with its run, even with two
  // runs writing at once; the last one at 100 %.
  for (const std::string label : {"tiny x1: step ", "tiny x2: step "}) {
    const int steps = runs[label == "tiny x1: step " ? 0 : 1].at("steps").get<int>();
    int lines = 0;
    std::istringstream out(run.out);
    std::string line;
    std::string last;
    while (std::getline(out, line))
      if (line.rfind(label, 0) == 0) {
        ++lines;
        last = line;
        EXPECT_NE(line.find(" substeps, "), std::string::npos) << line;
        EXPECT_EQ(line.back(), 's') << line;
      }
    EXPECT_EQ(lines, steps) << run.out;
    EXPECT_NE(last.find("(100.0 %)"), std::string::npos) << last;
  }
  const CliRun bad = run_brb("validate " + shell_quoted(folder.string()) + " --progress=-1");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--progress: must be a number of seconds >= 0"), std::string::npos)
      << bad.err;
}

// --threads: each run's elements evaluated on threads give the same results (checks and
// hysteresis bytes); the invocation in the report names it; a count below 1 is refused.
TEST(ValidateCli, ThreadsGiveTheSameResultsAndMustBeAtLeastOne) {
  const ScratchDirectory scratch;
  const fs::path folder = make_folder(scratch);
  const CliRun plain = run_brb("validate " + shell_quoted(folder.string()) + " --only tiny");
  ASSERT_TRUE(plain.exit_code == 0 || plain.exit_code == 1) << plain.err;
  const json plain_report = json::parse(read_file(folder / "report.json"));
  const std::string plain_hysteresis = read_file(folder / "tiny/out/x1/hysteresis.csv");

  const CliRun threaded =
      run_brb("validate " + shell_quoted(folder.string()) + " --only tiny --threads 2");
  EXPECT_EQ(threaded.exit_code, plain.exit_code) << threaded.err;
  const json report = json::parse(read_file(folder / "report.json"));
  EXPECT_EQ(report.at("specimens").at(0).at("runs").at(0).at("checks"),
            plain_report.at("specimens").at(0).at("runs").at(0).at("checks"));
  EXPECT_EQ(read_file(folder / "tiny/out/x1/hysteresis.csv"), plain_hysteresis);
  EXPECT_NE(read_file(folder / "REPORT.md").find("--threads 2"), std::string::npos);

  const CliRun bad = run_brb("validate " + shell_quoted(folder.string()) + " --threads 0");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--threads"), std::string::npos) << bad.err;
}

// --checkpoint-dir: each run writes DIR/<id>_x<k>.checkpoint while it runs and removes it
// once its outputs are written, with the results of a run without checkpoints; a file there
// that is not that run's checkpoint is refused (exit 2). Taking a run up is brb cyclic's code
// (run_cyclic_test), tested there.
TEST(ValidateCli, CheckpointDirectoryKeepsAFilePerRunUntilItsOutputsAreWritten) {
  const ScratchDirectory scratch;
  const fs::path folder = make_folder(scratch);
  const CliRun plain = run_brb("validate " + shell_quoted(folder.string()) + " --only tiny");
  ASSERT_TRUE(plain.exit_code == 0 || plain.exit_code == 1) << plain.err;
  const json plain_report = json::parse(read_file(folder / "report.json"));

  const fs::path checkpoints = scratch.path() / "checkpoints";
  const std::string command = "validate " + shell_quoted(folder.string()) +
                              " --only tiny --refinements 1,2 --checkpoint-dir " +
                              shell_quoted(checkpoints.string()) + " --checkpoint-every 1e-9";
  const CliRun run = run_brb(command);
  ASSERT_TRUE(run.exit_code == 0 || run.exit_code == 1) << run.err;
  ASSERT_TRUE(fs::is_directory(checkpoints));
  EXPECT_TRUE(fs::is_empty(checkpoints));
  const json report = json::parse(read_file(folder / "report.json"));
  const json& runs = report.at("specimens").at(0).at("runs");
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].at("checks"), plain_report.at("specimens").at(0).at("runs").at(0).at("checks"));

  scratch.write("checkpoints/tiny_x2.checkpoint", "not a checkpoint");
  const CliRun refused = run_brb(command);
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("tiny_x2.checkpoint: not a checkpoint of brb cyclic"),
            std::string::npos)
      << refused.err;
}

// A run killed after its first checkpoint is taken up by the same command: its report says
// from which step, with the results of the run that never stopped. The specimen is the
// source's small BRB of case 3 (validation/thesis_small_case3's brace and protocol, a few
// seconds), so that the run is still going when it is killed.
TEST(ValidateCli, AKilledRunIsTakenUpFromItsCheckpointAndTheReportSaysSo) {
  const ScratchDirectory scratch;
  const fs::path source = fs::path(BRB_SOURCE_DIR) / "validation" / "thesis_small_case3";
  fs::create_directories(scratch.path() / "validation" / "case3");
  scratch.write("validation/case3/brace.json", read_file(source / "brace.json"));
  scratch.write("validation/case3/protocol.json", read_file(source / "protocol.json"));
  json metrics = tiny_metrics();
  metrics["id"] = "case3";
  metrics["metrics"] = json::array(
      {{{"name", "loop energy"}, {"kind", "cycle_energy"}, {"cycle", 7}, {"unit", "N mm"}}});
  scratch.write("validation/case3/metrics.json", metrics.dump(2));
  const fs::path folder = scratch.path() / "validation";
  const fs::path checkpoints = scratch.path() / "checkpoints";
  const fs::path checkpoint = checkpoints / "case3_x1.checkpoint";
  const std::string arguments = " validate " + shell_quoted(folder.string()) +
                                " --checkpoint-dir " + shell_quoted(checkpoints.string()) +
                                " --checkpoint-every 1e-9";

  const CliRun whole = run_brb("validate " + shell_quoted(folder.string()));
  ASSERT_TRUE(whole.exit_code == 0 || whole.exit_code == 1) << whole.err;
  const json whole_report = json::parse(read_file(folder / "report.json"));

  ASSERT_TRUE(run_brb_until_checkpoint(arguments, checkpoint))
      << "no checkpoint written, or the run ended before it was killed";

  const CliRun taken_up = run_brb(arguments);
  ASSERT_TRUE(taken_up.exit_code == 0 || taken_up.exit_code == 1) << taken_up.err;
  EXPECT_NE(taken_up.out.find("checkpoint " + checkpoint.string() + " found"), std::string::npos)
      << taken_up.out;
  EXPECT_NE(taken_up.out.find("(taken up from a checkpoint at step "), std::string::npos)
      << taken_up.out;
  EXPECT_FALSE(fs::exists(checkpoint));
  const json report = json::parse(read_file(folder / "report.json"));
  const json& run = report.at("specimens").at(0).at("runs").at(0);
  EXPECT_GE(run.at("resumed_from_step").get<int>(), 1);
  EXPECT_EQ(whole_report.at("specimens").at(0).at("runs").at(0).at("resumed_from_step"), 0);
  EXPECT_EQ(run.at("checks"), whole_report.at("specimens").at(0).at("runs").at(0).at("checks"));
  EXPECT_EQ(run.at("iterations"),
            whole_report.at("specimens").at(0).at("runs").at(0).at("iterations"));
  EXPECT_NE(read_file(folder / "REPORT.md").find("(taken up from a checkpoint at step "),
            std::string::npos);
}

TEST(ValidateCli, InputErrorsExitWithTwoAndWriteNothing) {
  const ScratchDirectory scratch;
  json metrics = tiny_metrics();
  metrics["metrics"][0]["kind"] = "peak";
  const fs::path folder = make_folder(scratch, metrics);
  const CliRun bad_kind = run_brb("validate " + shell_quoted(folder.string()));
  EXPECT_EQ(bad_kind.exit_code, 2);
  EXPECT_NE(bad_kind.err.find("metrics.json: /metrics/0/kind: unknown metric kind \"peak\""),
            std::string::npos)
      << bad_kind.err;
  EXPECT_FALSE(fs::exists(folder / "REPORT.md"));
  EXPECT_FALSE(fs::exists(folder / "tiny" / "out"));

  const fs::path good = make_folder(scratch);
  const CliRun unknown = run_brb("validate " + shell_quoted(good.string()) + " --only nobody");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("--only: no specimen \"nobody\""), std::string::npos) << unknown.err;

  json brace = tiny_brace();
  brace["core"]["yielding_length"] = -100.0;
  scratch.write("validation/tiny/brace.json", brace.dump());
  const CliRun bad_brace = run_brb("validate " + shell_quoted(good.string()));
  EXPECT_EQ(bad_brace.exit_code, 2);
  EXPECT_NE(bad_brace.err.find("brace.json: /core/yielding_length"), std::string::npos)
      << bad_brace.err;
  EXPECT_FALSE(fs::exists(good / "REPORT.md"));
  EXPECT_FALSE(fs::exists(good / "tiny" / "out"));

  const CliRun bad_option = run_brb("validate " + shell_quoted(good.string()) + " --refinements 0");
  EXPECT_EQ(bad_option.exit_code, 2);
  EXPECT_NE(bad_option.err.find("--refinements"), std::string::npos) << bad_option.err;

  const CliRun no_folder = run_brb("validate " + shell_quoted((scratch.path() / "none").string()));
  EXPECT_EQ(no_folder.exit_code, 2);
  EXPECT_NE(no_folder.err.find("not a directory"), std::string::npos) << no_folder.err;
}

TEST(ValidateCli, ComparesWithAnExternalSolversCsvAndRefusesBadUnits) {
  // A reference made from the model's own first run (its hysteresis.csv re-exported with the
  // solver's column names, force in kN): the second run compares with it at zero error (to
  // the round-off of the kN conversion), and the stocky plate fails in neither.
  const ScratchDirectory scratch;
  const fs::path folder = make_folder(scratch);
  // Two cycles, so that one full cycle (maximum to maximum) is compared.
  scratch.write("validation/tiny/protocol.json",
                R"({"units": "dy", "cycles": [{"amplitude": 2, "cycles": 2}], "max_step": 0.25})");
  const CliRun first = run_brb("validate " + shell_quoted(folder.string()));
  ASSERT_TRUE(first.exit_code == 0 || first.exit_code == 1) << first.err;
  const fs::path hysteresis = folder / "tiny" / "out" / "x1" / "hysteresis.csv";
  const auto deformation = brb::io::read_numeric_column(hysteresis, "deformation").values;
  const auto force = brb::io::read_numeric_column(hysteresis, "force").values;
  std::string csv = "Frame,U1 (mm),RF1 (kN)\n";
  for (std::size_t k = 0; k < force.size(); ++k) {
    csv += std::to_string(k) + "," + brb::io::format_number(deformation[k]) + "," +
           brb::io::format_number(force[k] / 1000.0) + "\n";
  }
  scratch.write("validation/tiny/abaqus.csv", csv);

  json metrics = tiny_metrics();
  metrics["reference"] = {{"type", "solver_csv"},
                          {"file", "abaqus.csv"},
                          {"columns", {{"deformation", "U1 (mm)"}, {"force", "RF1 (kN)"}}},
                          {"units", {{"force", "kN"}, {"length", "mm"}}},
                          {"failure", {{"failure_mode", "none"}}}};
  metrics["metrics"] =
      json::array({{{"name", "nrms"},
                    {"kind", "record_nrms"},
                    {"reference", 0.0},
                    {"tolerance", {{"absolute", 1e-12}}}},
                   {{"name", "peaks"},
                    {"kind", "record_peak_force"},
                    {"reference", 0.0},
                    {"tolerance", {{"absolute", 1e-12}}}},
                   {{"name", "failure"}, {"kind", "record_failure_mode"}, {"expected", true}}});
  scratch.write("validation/tiny/metrics.json", metrics.dump(2));
  const CliRun second = run_brb("validate " + shell_quoted(folder.string()));
  ASSERT_TRUE(second.exit_code == 0 || second.exit_code == 1) << second.err;
  const json report = json::parse(read_file(folder / "report.json"));
  const json& checks = report.at("specimens").at(0).at("runs").at(0).at("checks");
  ASSERT_EQ(checks.size(), 6u);
  for (std::size_t i = 3; i < 6; ++i)
    EXPECT_EQ(checks[i].at("status"), "pass") << checks[i].dump();
  EXPECT_EQ(checks[5].at("value"), 1.0);
  // The failure needs the step history: written as `brb cyclic --histories` does.
  EXPECT_TRUE(fs::is_regular_file(folder / "tiny" / "out" / "x1" / "element_history.csv"));

  metrics["reference"]["units"]["force"] = "lbf";
  scratch.write("validation/tiny/metrics.json", metrics.dump(2));
  fs::remove(folder / "REPORT.md");
  const CliRun bad_unit = run_brb("validate " + shell_quoted(folder.string()));
  EXPECT_EQ(bad_unit.exit_code, 2);
  EXPECT_NE(bad_unit.err.find("metrics.json: /reference/units/force: unknown force unit"),
            std::string::npos)
      << bad_unit.err;
  EXPECT_FALSE(fs::exists(folder / "REPORT.md"));
}

} // namespace
