// The validation report built from hand-made outcomes: the tally, the summary line, the
// per-run tables of REPORT.md, report.json, and the contrasts evaluated across specimens.
#include "brb/validation/contrast.hpp"
#include "brb/validation/report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

using brb::validation::CheckResult;
using brb::validation::CheckStatus;
using brb::validation::ContrastSpec;
using brb::validation::RunOutcome;
using brb::validation::SpecimenOutcome;
using brb::validation::Tolerance;
using brb::validation::ValidationReport;

CheckResult check(const std::string& name, double value, CheckStatus status) {
  CheckResult result;
  result.name = name;
  result.kind = "peak_force";
  result.unit = "N";
  result.value = value;
  result.status = status;
  return result;
}

/// Specimen `id` run at refinement 1 with a beta metric of value `beta` (reported) and an
/// energy check against 4477444.559 N mm within 5 % that passes or fails.
SpecimenOutcome specimen(const std::string& id, double beta, double energy_value) {
  SpecimenOutcome outcome;
  outcome.specimen.id = id;
  outcome.specimen.title = "title of " + id;
  outcome.specimen.source = "facts";
  outcome.specimen.notes = {"an assumption"};
  RunOutcome run;
  run.refinement = 1;
  run.core_elements = 16;
  run.output_directory = "validation/" + id + "/out/x1";
  run.completed = true;
  run.steps = 682;
  run.planned_steps = 682;
  run.run_seconds = 12.5;
  run.energy_balance_error = 3e-4;
  run.checks.push_back(check("beta", beta, CheckStatus::reported));
  CheckResult energy = check("energy", energy_value, CheckStatus::pass);
  energy.unit = "N mm";
  energy.reference = 4477444.559;
  energy.tolerance = Tolerance{Tolerance::Kind::relative, 0.05};
  energy.error = (energy_value - 4477444.559) / 4477444.559;
  energy.status = std::abs(*energy.error) <= 0.05 ? CheckStatus::pass : CheckStatus::fail;
  run.checks.push_back(energy);
  outcome.runs.push_back(run);
  return outcome;
}

ContrastSpec greater_beta(const std::string& left, const std::string& right) {
  ContrastSpec contrast;
  contrast.name = left + " > " + right;
  contrast.statement = "beta of " + left + " is larger";
  contrast.source = "facts 8";
  contrast.left = {left, "beta"};
  contrast.relation = ">";
  contrast.right = {right, "beta"};
  return contrast;
}

TEST(Contrasts, HoldFailOrAreNotCheckedWhenASpecimenDidNotRun) {
  const std::vector<SpecimenOutcome> outcomes{specimen("G1", 1.3, 4.5e6),
                                              specimen("G3", 1.1, 4.5e6)};
  const auto results = brb::validation::evaluate_contrasts(
      {greater_beta("G1", "G3"), greater_beta("G3", "G1"), greater_beta("G1", "G9")}, outcomes);
  ASSERT_EQ(results.size(), 3u);
  EXPECT_EQ(results[0].status, CheckStatus::pass);
  EXPECT_EQ(*results[0].left, 1.3);
  EXPECT_EQ(*results[0].right, 1.1);
  EXPECT_EQ(*results[0].refinement, 1);
  EXPECT_EQ(results[1].status, CheckStatus::fail);
  EXPECT_EQ(results[2].status, CheckStatus::reported);
  EXPECT_FALSE(results[2].refinement);
}

ValidationReport two_specimens() {
  ValidationReport report;
  report.validation_directory = "validation";
  // D3's energy 4.7e6 is 4.97 % above the reference (pass); D4's 4.0e6 is 10.7 % below (fail).
  report.specimens = {specimen("D3", 1.05, 4.7e6), specimen("D4", 1.02, 4.0e6)};
  report.contrasts =
      brb::validation::evaluate_contrasts({greater_beta("D3", "D4")}, report.specimens);
  return report;
}

TEST(Report, TallyCountsChecksAndContrasts) {
  const auto counts = brb::validation::tally(two_specimens());
  EXPECT_EQ(counts.passed, 2); // D3 energy, the contrast
  EXPECT_EQ(counts.failed, 1); // D4 energy
  EXPECT_EQ(counts.reported, 2);
  EXPECT_FALSE(counts.all_passed());
}

TEST(Report, MarkdownHasTheSummaryFirstAndOneTablePerRun) {
  const std::string markdown = brb::validation::report_markdown(two_specimens());
  EXPECT_EQ(markdown.find("# Validation report\n\n**FAIL**: 2 checks passed, 1 failed, 2 values "
                          "reported"),
            0u)
      << markdown;
  EXPECT_NE(markdown.find("## D3: title of D3"), std::string::npos);
  EXPECT_NE(markdown.find("### D4, refinement x1 (16 core elements)"), std::string::npos);
  EXPECT_NE(markdown.find("| metric | reference | result | error | tolerance | pass |"),
            std::string::npos);
  // reference, result, relative error in percent, tolerance, verdict
  EXPECT_NE(markdown.find("| energy | 4.47744e+06 N mm | 4.7e+06 N mm | +4.97 % | 5 % | pass |"),
            std::string::npos)
      << markdown;
  EXPECT_NE(markdown.find("| energy | 4.47744e+06 N mm | 4e+06 N mm | -10.66 % | 5 % | FAIL |"),
            std::string::npos)
      << markdown;
  EXPECT_NE(markdown.find("| D3 | x1 | yes | 682 / 682 | 12.5 | 0.0003 | 0 | 1 | 0 | 1 |"),
            std::string::npos)
      << markdown;
  EXPECT_NE(markdown.find("- hysteresis and summary: `D3/out/x1/`"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("## Contrasts"), std::string::npos);
  EXPECT_NE(markdown.find("| D3 > D4 | x1 | D3 beta = 1.05 | greater than | D4 beta = 1.02 | "
                          "pass |"),
            std::string::npos)
      << markdown;
}

TEST(Report, JsonCarriesEveryValueAtFullPrecision) {
  const auto json = brb::validation::report_json(two_specimens());
  EXPECT_EQ(json.at("passed"), false);
  EXPECT_EQ(json.at("checks").at("failed"), 1);
  const auto& energy = json.at("specimens").at(1).at("runs").at(0).at("checks").at(1);
  EXPECT_EQ(energy.at("name"), "energy");
  EXPECT_EQ(energy.at("value"), 4.0e6);
  EXPECT_EQ(energy.at("reference"), 4477444.559);
  EXPECT_EQ(energy.at("tolerance").at("relative"), 0.05);
  EXPECT_EQ(energy.at("status"), "fail");
  EXPECT_EQ(json.at("contrasts").at(0).at("status"), "pass");
  EXPECT_TRUE(json.at("specimens").at(0).at("reference").is_null());
}

TEST(Report, NamesTheReferenceItsTypeAndItsStatedFailure) {
  ValidationReport report = two_specimens();
  brb::validation::RecordReference reference;
  reference.type = brb::validation::ReferenceType::solver_csv;
  reference.written = "abaqus/D3.csv";
  reference.failure =
      brb::validation::FailureEvent{brb::validation::FailureMode::casing_failure, 3};
  report.specimens.at(1).specimen.record = reference;
  const auto json = brb::validation::report_json(report);
  const auto& written = json.at("specimens").at(1).at("reference");
  EXPECT_EQ(written.at("type"), "solver_csv");
  EXPECT_EQ(written.at("source"), "abaqus/D3.csv");
  EXPECT_EQ(written.at("failure").at("failure_mode"), "casing_failure");
  EXPECT_EQ(written.at("failure").at("cycle"), 3);
  const std::string markdown = brb::validation::report_markdown(report);
  EXPECT_NE(markdown.find("Compared with: solver_csv `abaqus/D3.csv`; it states failure "
                          "casing_failure in cycle 3."),
            std::string::npos)
      << markdown;
}

} // namespace
