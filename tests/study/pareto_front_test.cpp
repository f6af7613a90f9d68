// The Pareto front and the error metrics of the run-time-against-error study, on hand-made
// points and responses whose fronts and errors are worked out by hand in the comments.
#include "brb/io/input_error.hpp"
#include "brb/study/pareto_front.hpp"
#include "brb/study/pareto_metrics.hpp"
#include "brb/study/pareto_report.hpp"
#include "brb/study/pareto_runner.hpp"

#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using namespace brb::study;

constexpr double kInfinite = std::numeric_limits<double>::infinity();

TEST(ParetoFront, KeepsExactlyTheNonDominatedPoints) {
  const std::vector<TimeErrorPoint> points{
      {1.0, 0.10},         // A: fastest but one, on the front
      {2.0, 0.05},         // B: on the front
      {3.0, 0.05},         // C: B is faster with the same error: dominated
      {0.5, 0.50},         // D: the fastest: on the front
      {4.0, 0.0},          // E: the exact one: on the front
      {2.5, 0.20},         // F: dominated by B
      {0.1, std::nan("")}, // G: unknown error: never on the front
      {2.0, 0.05},         // H: equal to B: both stay
      {0.2, kInfinite},    // I: a failed comparison: never on the front
  };
  const std::vector<bool> front = pareto_front(points);
  const std::vector<bool> expected{true, true, false, true, true, false, false, true, false};
  EXPECT_EQ(front, expected);
}

TEST(ParetoFront, EmptyAndSinglePoints) {
  EXPECT_TRUE(pareto_front({}).empty());
  EXPECT_EQ(pareto_front({{3.0, 0.2}}), std::vector<bool>{true});
}

TEST(ParetoMetrics, ComponentErrorsFollowTheirDefinitions) {
  ComponentResponse reference;
  reference.completed = true;
  // Cycle 1 dissipates 1 N mm, under 5 % of the largest loop (200): left out of energy and
  // beta (its 100 % energy error is noise), kept for the peak forces.
  reference.cycles = {{1.0, 100.0, -100.0}, {100.0, 200.0, -210.0}, {200.0, 250.0, -270.0}};
  ComponentResponse run = reference;
  run.cycles = {{2.0, 101.0, -100.0}, {102.0, 200.0, -210.0}, {196.0, 250.0, -280.0}};
  const ParetoErrors errors = component_errors(reference, run);
  // energy: max(2 / 100, 4 / 200) = 0.02
  EXPECT_NEAR(*errors.cycle_energy, 0.02, 1e-15);
  // peak forces: max(1 / 100, 10 / 270)
  EXPECT_NEAR(*errors.peak_force, 10.0 / 270.0, 1e-15);
  // beta of cycle 3: 270 / 250 against 280 / 250: 10 / 270
  EXPECT_NEAR(*errors.beta, 10.0 / 270.0, 1e-15);
  EXPECT_DOUBLE_EQ(errors.primary(), *errors.cycle_energy);
  EXPECT_NEAR(errors.worst(), 10.0 / 270.0, 1e-15); // beta and peak forces tie
  EXPECT_FALSE(errors.peak_drift.has_value());
  EXPECT_FALSE(errors.solid.has_value());

  ComponentResponse short_run = run;
  short_run.cycles.pop_back();
  EXPECT_EQ(component_errors(reference, short_run).primary(), kInfinite);
  EXPECT_EQ(component_errors(reference, reference).worst(), 0.0);
}

TEST(ParetoMetrics, SolidErrorComparesTheRunsCyclesWithThe3DRunsFirstOnes) {
  // The 3D run went one cycle further (its protocol begins with the run's): only the run's
  // cycles count, with the 3D run as the reference of the cycle-energy definition.
  ComponentResponse solid;
  solid.completed = true;
  solid.cycles = {
      {100.0, 200.0, -210.0, 1.0}, {200.0, 250.0, -270.0, 2.0}, {400.0, 260.0, -280.0, 4.0}};
  ComponentResponse run;
  run.completed = true;
  run.cycles = {{103.0, 200.0, -210.0, 1.0}, {190.0, 250.0, -270.0, 2.0}};
  const std::optional<double> error = solid_cycle_energy_error(solid, run);
  ASSERT_TRUE(error.has_value());
  EXPECT_NEAR(*error, 10.0 / 200.0, 1e-15); // max(3 / 100, 10 / 200)

  // nothing to compare: the run stopped early, the 3D run is shorter, or another protocol
  ComponentResponse stopped = run;
  stopped.completed = false;
  EXPECT_FALSE(solid_cycle_energy_error(solid, stopped).has_value());
  ComponentResponse longer = run;
  longer.cycles.push_back({400.0, 260.0, -280.0, 4.0});
  longer.cycles.push_back({400.0, 260.0, -280.0, 4.0});
  EXPECT_FALSE(solid_cycle_energy_error(solid, longer).has_value());
  ComponentResponse other_amplitude = run;
  other_amplitude.cycles[1].amplitude = 2.0 * (1.0 + 2.0 * kSolidAmplitudeTolerance);
  EXPECT_FALSE(solid_cycle_energy_error(solid, other_amplitude).has_value());
  other_amplitude.cycles[1].amplitude = 2.0 * (1.0 + 0.5 * kSolidAmplitudeTolerance);
  EXPECT_TRUE(solid_cycle_energy_error(solid, other_amplitude).has_value());
}

TEST(ParetoMetrics, FrameErrorsFollowTheirDefinitions) {
  FrameResponse reference;
  reference.completed = true;
  reference.end_time = 3.0;
  reference.max_drift = {0.01, 0.02};
  reference.residual_drift = {0.001, 0.002};
  reference.cid = {4.0, 10.0};
  FrameResponse run = reference;
  run.max_drift = {0.0105, 0.019};
  run.residual_drift = {0.0012, 0.002};
  run.cid = {5.0, 10.0};
  const ParetoErrors errors = frame_errors(reference, run);
  EXPECT_NEAR(*errors.peak_drift, 0.05, 1e-12);     // 0.0005 / 0.01 and 0.001 / 0.02
  EXPECT_NEAR(*errors.residual_drift, 0.01, 1e-12); // 0.0002 / 0.02 (largest peak drift)
  EXPECT_NEAR(*errors.cid, 0.1, 1e-12);             // 1 / 10 (largest reference CID)
  EXPECT_DOUBLE_EQ(errors.primary(), *errors.peak_drift);
  EXPECT_FALSE(errors.cycle_energy.has_value());

  // Braces that stay elastic: CID measured against 1 dy, not against ~0.
  FrameResponse elastic = reference;
  elastic.cid = {0.0, 0.01};
  FrameResponse elastic_run = elastic;
  elastic_run.cid = {0.0, 0.03};
  EXPECT_NEAR(*frame_errors(elastic, elastic_run).cid, 0.02, 1e-12);

  FrameResponse stopped = run;
  stopped.end_time = 2.0; // a collapse or a failed step before the window's end
  EXPECT_EQ(frame_errors(reference, stopped).primary(), kInfinite);
}

TEST(ParetoMetrics, MedianOfRepeats) {
  EXPECT_DOUBLE_EQ(median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_DOUBLE_EQ(median({4.0, 1.0, 2.0, 3.0}), 2.5);
  EXPECT_DOUBLE_EQ(median({}), 0.0);
}

/// A hand-made outcome: a reference `full`, a cheap setting with the reference's response (it
/// dominates the reference) and a cheaper one with 10 % energy error.
CaseOutcome hand_made_case() {
  CaseOutcome outcome;
  outcome.study_case.kind = CaseKind::component;
  ComponentResponse reference;
  reference.completed = true;
  reference.cycles = {{100.0, 200.0, -210.0}};
  ComponentResponse coarse = reference;
  coarse.cycles[0].energy = 110.0;
  const auto setting = [](std::string label, SettingFidelity fidelity, double time,
                          ComponentResponse response) {
    SettingOutcome s;
    s.setting.label = std::move(label);
    s.setting.fidelity = fidelity;
    s.ran = true;
    s.wall_times = {time};
    s.median_time = time;
    s.component = std::move(response);
    return s;
  };
  outcome.settings = {setting("full-16", SettingFidelity::full, 100.0, reference),
                      setting("truss", SettingFidelity::truss, 0.01, reference),
                      setting("rough", SettingFidelity::truss, 0.001, coarse)};
  outcome.study_case.reference = 0;
  return outcome;
}

TEST(ParetoCase, ErrorsAgainstTheReferenceAndTheFront) {
  CaseOutcome outcome = hand_made_case();
  evaluate_case(outcome);
  EXPECT_EQ(outcome.settings[0].errors.primary(), 0.0);
  EXPECT_EQ(outcome.settings[1].errors.primary(), 0.0);
  EXPECT_NEAR(outcome.settings[2].errors.primary(), 0.1, 1e-15);
  // the truss matches the reference 10,000 times faster: the reference is off the front
  EXPECT_FALSE(outcome.settings[0].front_primary);
  EXPECT_TRUE(outcome.settings[1].front_primary);
  EXPECT_TRUE(outcome.settings[2].front_primary);
  EXPECT_EQ(cheapest_within(outcome, kAcceptanceError), std::optional<std::size_t>{1});
  EXPECT_EQ(cheapest_within(outcome, 0.2), std::optional<std::size_t>{2});

  // A failed reference: no error can be measured, nothing is on the front.
  CaseOutcome failed = hand_made_case();
  failed.settings[0].ran = false;
  failed.settings[0].failure = "diverged";
  evaluate_case(failed);
  for (const SettingOutcome& s : failed.settings) {
    EXPECT_EQ(s.errors.primary(), kInfinite);
    EXPECT_FALSE(s.front_primary);
  }
  EXPECT_FALSE(cheapest_within(failed, kAcceptanceError).has_value());
}

TEST(ParetoReport, CsvHasOneRowPerSettingAndMarksTheFront) {
  CaseOutcome outcome = hand_made_case();
  outcome.study_case.name = "hand";
  evaluate_case(outcome);
  const std::string csv = pareto_csv({outcome});
  std::istringstream lines(csv);
  std::string header, row;
  std::getline(lines, header);
  EXPECT_EQ(header.substr(0, 22), "case,kind,setting,refe");
  std::vector<std::string> rows;
  while (std::getline(lines, row))
    rows.push_back(row);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].substr(0, 20), "hand,component,full-");
  // front_primary, front_worst, status are the last three columns
  EXPECT_NE(rows[1].find(",1,1,completed"), std::string::npos) << rows[1];
  EXPECT_NE(rows[0].find(",0,0,completed"), std::string::npos) << rows[0];
  ParetoRunDescription description;
  description.command_line = "brb bench pareto";
  const std::string page = pareto_markdown({outcome}, description);
  EXPECT_NE(page.find("`truss` (0.00 %"), std::string::npos);
  EXPECT_NE(page.find("brb solid"), std::string::npos);
}

TEST(ParetoReport, ASolidRunGivesEachSettingsEnergyErrorAgainstIt) {
  // The 3D run's loop is 100 / 1.25 = 80 N mm: the reference (100) and the truss are 25 % off
  // it, the rough setting (110) 37.5 %; a case without one shows n/a.
  CaseOutcome outcome = hand_made_case();
  outcome.study_case.name = "hand";
  SolidReference solid;
  solid.file = "solid/x1/summary.json";
  solid.run_seconds = 1000.0;
  solid.response.completed = true;
  solid.response.cycles = {{80.0, 190.0, -200.0}};
  outcome.solid = solid;
  evaluate_case(outcome);
  EXPECT_NEAR(*outcome.settings[0].errors.solid, 0.25, 1e-15);
  EXPECT_NEAR(*outcome.settings[2].errors.solid, 0.375, 1e-15);
  // not part of the errors against the finest full setting
  EXPECT_EQ(outcome.settings[0].errors.worst(), 0.0);
  ParetoRunDescription description;
  description.command_line = "brb bench pareto";
  const std::string page = pareto_markdown({outcome}, description);
  EXPECT_NE(page.find("| 25.0 % | "), std::string::npos) << page;
  EXPECT_NE(page.find("| 37.5 % | "), std::string::npos) << page;
  EXPECT_NE(page.find("`solid/x1/summary.json`, 1000 s"), std::string::npos) << page;
  EXPECT_NE(page.find("10 times the reference setting's time"), std::string::npos) << page;
  const std::string without = pareto_markdown({hand_made_case()}, description);
  EXPECT_NE(without.find("| n/a | "), std::string::npos);
}

TEST(ParetoReport, ReadsTheCyclesOfABrbSolidSummary) {
  const brb::testing::ScratchDirectory scratch;
  const auto file = scratch.write("summary.json",
                                  R"({"completed": true, "solid": {"run_seconds": 12.5}, "cycles": [
          {"index": 1, "amplitude": 0.7, "energy": 142.5, "max_tension": 25980.0,
           "max_compression": -26083.0}]})");
  const SolidReference solid = read_solid_reference(file);
  EXPECT_EQ(solid.run_seconds, 12.5);
  EXPECT_TRUE(solid.response.completed);
  ASSERT_EQ(solid.response.cycles.size(), 1u);
  EXPECT_EQ(solid.response.cycles[0].amplitude, 0.7);
  EXPECT_EQ(solid.response.cycles[0].energy, 142.5);
  EXPECT_EQ(solid.response.cycles[0].max_compression, -26083.0);
  const auto bad = scratch.write("bad.json", R"({"completed": true, "cycles": []})");
  try {
    (void)read_solid_reference(bad);
    ADD_FAILURE() << "a summary without its solid block was read";
  } catch (const brb::io::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("solid"), std::string::npos) << error.what();
    EXPECT_EQ(error.file(), bad.string());
  }
}

} // namespace
