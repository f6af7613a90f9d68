// The metric kinds of metrics.json on synthetic hysteresis records whose values are computed by
// hand: rectangle-shaped loops (loop energy = width x height of the rectangle), bilinear
// loading branches (offset yield force in closed form), and the judging of values against
// references, bounds and flags.
#include "brb/io/json_input.hpp"
#include "brb/validation/metric_kinds.hpp"
#include "brb/validation/specimen_run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include <utility>
#include <vector>

namespace {

using brb::analysis::CycleMetrics;
using brb::analysis::CyclicStep;
using brb::analysis::CyclicTestResult;
using brb::validation::CheckStatus;
using brb::validation::find_metric_kind;
using brb::validation::judge;
using brb::validation::MetricSpec;
using brb::validation::MetricValue;
using brb::validation::RunData;
using brb::validation::Tolerance;
using nlohmann::json;

constexpr double kForce = 1000.0;    // N, the loops' tension force F
constexpr double kHalfWidth = 5.0;   // mm, the first loops' amplitude a
constexpr double kYieldDeform = 1.0; // mm, dy of the synthetic brace (so a = 5 dy)

/// Appends the corners of a rectangular loop of half-width `amplitude`, force `tension` on the
/// tension side and `compression` (< 0) on the compression side, as cycle `index`:
/// (0, T) -> (a, T) -> (a, C) -> (-a, C) -> (-a, T) -> (0, T). By the trapezoidal rule its
/// area is exactly 2a x (T - C): the vertical legs add nothing, the horizontal ones T a,
/// -C 2a and T a.
void add_rectangle(CyclicTestResult& result, int index, double amplitude, double tension,
                   double compression) {
  const std::vector<std::pair<double, double>> corners{
      {0.0, tension},           {amplitude, tension},
      {amplitude, compression}, {-amplitude, compression},
      {-amplitude, tension},    {0.0, tension}};
  for (const auto& [deformation, force] : corners) {
    CyclicStep step;
    step.step = static_cast<int>(result.steps.size());
    step.cycle = index;
    step.deformation = deformation;
    step.force = force;
    result.steps.push_back(step);
  }
  result.cycles.push_back(CycleMetrics{index, amplitude, 0.0, tension, compression});
}

/// Three rectangles: cycle 1 at a (T = F, C = -1.2 F), cycle 2 at a (T = 2 F, C = -2 F),
/// cycle 3 at 2a (T = 1.5 F, C = -3 F).
CyclicTestResult three_rectangles() {
  CyclicTestResult result;
  result.steps.push_back(CyclicStep{0, 0, 0.0, 0.0, 0.0, 0});
  add_rectangle(result, 1, kHalfWidth, kForce, -1.2 * kForce);
  add_rectangle(result, 2, kHalfWidth, 2.0 * kForce, -2.0 * kForce);
  add_rectangle(result, 3, 2.0 * kHalfWidth, 1.5 * kForce, -3.0 * kForce);
  result.completed = true;
  return result;
}

MetricValue evaluate(const json& metric, const CyclicTestResult& result,
                     double yielding_length = 100.0) {
  const RunData run{result, kYieldDeform, kForce, yielding_length};
  return find_metric_kind(metric.at("kind").get<std::string>())->evaluate(metric, run);
}

TEST(CycleEnergySpread, RangeOverMeanOfTheChosenCycles) {
  // Reference (definition): energies 100, 102, 98 N mm -> (102 - 98) / 100 = 0.04; cycle 1
  // (1000 N mm) is outside the range asked for.
  CyclicTestResult result = three_rectangles();
  result.cycles = {CycleMetrics{1, 1.0, 1000.0, 0.0, 0.0}, CycleMetrics{2, 1.0, 100.0, 0.0, 0.0},
                   CycleMetrics{3, 1.0, 102.0, 0.0, 0.0}, CycleMetrics{4, 1.0, 98.0, 0.0, 0.0}};
  const MetricValue spread =
      evaluate({{"kind", "cycle_energy_spread"}, {"first_cycle", 2}, {"last_cycle", 4}}, result);
  ASSERT_TRUE(spread.value);
  EXPECT_NEAR(*spread.value, 0.04, 1e-12);
  const MetricValue beyond =
      evaluate({{"kind", "cycle_energy_spread"}, {"first_cycle", 2}, {"last_cycle", 5}}, result);
  EXPECT_FALSE(beyond.value);
}

TEST(ResidualCompressionRatio, ForceAtTheLargestShorteningOverThePeak) {
  // Reference (definition): a compression excursion that peaks at -1000 N at -2 mm and falls
  // to -50 N at -3 mm (the largest shortening), then recovers in tension: 50 / 1000.
  CyclicTestResult result;
  const std::vector<std::pair<double, double>> path{{0.0, 0.0},    {-1.0, -800.0}, {-2.0, -1000.0},
                                                    {-3.0, -50.0}, {-1.0, 900.0},  {1.0, 1100.0}};
  for (const auto& [deformation, force] : path) {
    CyclicStep step;
    step.step = static_cast<int>(result.steps.size());
    step.cycle = 1;
    step.deformation = deformation;
    step.force = force;
    result.steps.push_back(step);
  }
  const MetricValue ratio = evaluate({{"kind", "residual_compression_ratio"}}, result);
  ASSERT_TRUE(ratio.value);
  EXPECT_NEAR(*ratio.value, 0.05, 1e-12);
}

/// The loops as a lab record (the reversal threshold of the specimens, 0.1 dy = 0.1 mm), and
/// the model: the same loops with the tension force times `tension_factor` and the
/// compression force times `compression_factor`.
struct RecordAndModel {
  brb::validation::RecordSeries record;
  CyclicTestResult model;
};

RecordAndModel record_and_scaled_model(const CyclicTestResult& loops, double tension_factor,
                                       double compression_factor) {
  RecordAndModel pair{{}, loops};
  for (std::size_t k = 0; k < loops.steps.size(); ++k) {
    const double force = loops.steps[k].force;
    pair.record.deformation.push_back(loops.steps[k].deformation);
    pair.record.test_force.push_back(force);
    pair.model.steps[k].force = force * (force > 0.0 ? tension_factor : compression_factor);
  }
  pair.record.reversal_threshold = 0.1;
  return pair;
}

TEST(RecordKinds, CompareTheModelWithItsLabRecordAtTheRecordsPoints) {
  // Reference (definition, record_comparison.hpp): a model force 10 % above the test force
  // everywhere has a normalised RMS error of 0.1, loop energies 10 % high and the same beta.
  // Points marked NaN in the record are not compared (here a model spike of 1e9 N).
  auto [record, model] = record_and_scaled_model(three_rectangles(), 1.1, 1.1);
  record.test_force[3] = std::nan("");
  model.steps[3].force = 1e9;
  const RunData run{model, kYieldDeform, kForce, 100.0, &record};
  const auto value = [&](const char* kind) {
    return find_metric_kind(kind)->evaluate(json{{"kind", kind}}, run);
  };
  const MetricValue nrms = value("record_nrms");
  ASSERT_TRUE(nrms.value) << nrms.note;
  EXPECT_NEAR(*nrms.value, 0.1, 1e-12);
  const MetricValue energy = value("record_cycle_energy");
  ASSERT_TRUE(energy.value) << energy.note;
  EXPECT_NEAR(*energy.value, 0.1, 1e-12);
  const MetricValue beta = value("record_beta");
  ASSERT_TRUE(beta.value) << beta.note;
  EXPECT_NEAR(*beta.value, 0.0, 1e-12);
  // Without a record the kinds have no value and say why.
  const RunData bare{model, kYieldDeform, kForce, 100.0};
  EXPECT_FALSE(find_metric_kind("record_nrms")->evaluate(json::object(), bare).value);
}

/// The value of `metric` (its "kind" names the kind) on `run`.
MetricValue evaluate_on(const json& metric, const RunData& run) {
  return find_metric_kind(metric.at("kind").get<std::string>())->evaluate(metric, run);
}

TEST(RecordKinds, BetaHasNoValueWhereNoReferenceCycleHasATensionPeak) {
  // The three rectangles shifted down by 4 F (record and model alike): every force is
  // compressive, so no cycle reaches Py in tension and none has a beta to match
  // (record_comparison.hpp, beta_compared),
  // while the loop energies (a shift adds nothing to a closed loop) are still compared.
  auto [record, model] = record_and_scaled_model(three_rectangles(), 1.1, 1.1);
  for (std::size_t k = 0; k < record.test_force.size(); ++k) {
    record.test_force[k] -= 4.0 * kForce;
    model.steps[k].force -= 4.0 * kForce;
  }
  const RunData run{model, kYieldDeform, kForce, 100.0, &record};
  const MetricValue energy = evaluate_on({{"kind", "record_cycle_energy"}}, run);
  ASSERT_TRUE(energy.value) << energy.note;
  const MetricValue beta = evaluate_on({{"kind", "record_beta"}}, run);
  EXPECT_FALSE(beta.value) << *beta.value;
  EXPECT_NE(beta.note.find("no scored cycle of the reference reaches the yield force"),
            std::string::npos)
      << beta.note;
  const MetricValue first = evaluate_on({{"kind", "record_beta"}, {"compared_cycle", 1}}, run);
  EXPECT_FALSE(first.value);
  EXPECT_NE(first.note.find("compared cycle 1 of the reference has no tension peak"),
            std::string::npos)
      << first.note;
}

TEST(RecordKinds, AiscAdjustmentFactorsAreTheLargestOverTheCycles) {
  // Reference (definition, AISC 341 F4.2a as `brb check` takes it): beta = the largest
  // Pmax / Tmax over the scored cycles, omega = the largest Tmax over Pysc. The record is the
  // three rectangles (largest tension 2 F, in the cycles that hold rectangle 2's tension
  // side); the model's tension is 10 % higher and its compression 32 % higher everywhere, so
  // every cycle's beta is 1.2 times the record's (1.32 / 1.1) and the largest tension 2.2 F.
  const auto [record, model] = record_and_scaled_model(three_rectangles(), 1.1, 1.32);
  const RunData run{model, kYieldDeform, kForce, 100.0, &record};
  const MetricValue beta = evaluate_on({{"kind", "record_largest_beta"}}, run);
  ASSERT_TRUE(beta.value) << beta.note;
  const MetricValue per_cycle = evaluate_on({{"kind", "record_beta"}}, run);
  ASSERT_TRUE(per_cycle.value) << per_cycle.note;
  // the largest record beta B: model 1.2 B, so the difference is 0.2 B, and the per-cycle
  // differences 0.2 beta_k are at most that
  EXPECT_NEAR(*beta.value, *per_cycle.value, 1e-12);
  EXPECT_GT(*beta.value, 0.2 - 1e-12); // every beta here is >= 1
  const double pysc = 800.0;
  const json omega_metric{{"kind", "record_largest_omega"}, {"pysc", pysc}};
  const MetricValue omega = find_metric_kind("record_largest_omega")->evaluate(omega_metric, run);
  ASSERT_TRUE(omega.value) << omega.note;
  EXPECT_NEAR(*omega.value, 0.1 * 2.0 * kForce / pysc, 1e-12);
  EXPECT_NE(omega.note.find("reference 2.5"), std::string::npos) << omega.note;
  // omega needs Pysc
  const auto* omega_kind = find_metric_kind("record_largest_omega");
  EXPECT_THROW(omega_kind->check(brb::io::JsonValue(json{{"kind", "record_largest_omega"}},
                                                    "metrics.json", "/metrics/0")),
               brb::io::InputError);
  EXPECT_THROW(
      omega_kind->check(brb::io::JsonValue(json{{"kind", "record_largest_omega"}, {"pysc", -1.0}},
                                           "metrics.json", "/metrics/0")),
      brb::io::InputError);
}

TEST(CycleEnergy, RectangleLoopAreaIsWidthTimesHeight) {
  const CyclicTestResult result = three_rectangles();
  // cycle 1: 2a x 2.2F = 10 x 2200; cycle 3: 4a x 4.5F = 20 x 4500.
  const MetricValue first = evaluate({{"kind", "cycle_energy"}, {"cycle", 1}}, result);
  ASSERT_TRUE(first.value);
  EXPECT_NEAR(*first.value, 2.0 * kHalfWidth * 2.2 * kForce, 1e-9);
  const MetricValue third = evaluate({{"kind", "cycle_energy"}, {"cycle", 3}}, result);
  ASSERT_TRUE(third.value);
  EXPECT_NEAR(*third.value, 4.0 * kHalfWidth * 4.5 * kForce, 1e-9);
}

TEST(CycleEnergy, AmplitudeSelectsTheFirstCycleAtThatAmplitude) {
  const CyclicTestResult result = three_rectangles();
  // Cycles 1 and 2 are both at 5 dy: the first one's area (2a x 2.2F), not the second's
  // (2a x 4F).
  const MetricValue at_five = evaluate({{"kind", "cycle_energy"}, {"amplitude_dy", 5}}, result);
  ASSERT_TRUE(at_five.value);
  EXPECT_NEAR(*at_five.value, 2.0 * kHalfWidth * 2.2 * kForce, 1e-9);
  EXPECT_NE(at_five.note.find("cycle 1"), std::string::npos) << at_five.note;
  const MetricValue at_ten = evaluate({{"kind", "cycle_energy"}, {"amplitude_dy", 10}}, result);
  ASSERT_TRUE(at_ten.value);
  EXPECT_NEAR(*at_ten.value, 4.0 * kHalfWidth * 4.5 * kForce, 1e-9);
}

TEST(CycleEnergy, ACycleThatWasNotCompletedHasNoValueAndSaysWhy) {
  CyclicTestResult result = three_rectangles();
  result.cycles.pop_back(); // the run stopped in cycle 3
  const MetricValue missing = evaluate({{"kind", "cycle_energy"}, {"cycle", 3}}, result);
  EXPECT_FALSE(missing.value);
  EXPECT_NE(missing.note.find("cycle 3 was not completed"), std::string::npos) << missing.note;
  const MetricValue no_amplitude =
      evaluate({{"kind", "cycle_energy"}, {"amplitude_dy", 7}}, result);
  EXPECT_FALSE(no_amplitude.value);
}

TEST(PeakForce, PerCycleAndOverTheRunAsMagnitudes) {
  const CyclicTestResult result = three_rectangles();
  const auto peak = [&](const std::string& direction, json selector) {
    json metric = {{"kind", "peak_force"}, {"direction", direction}};
    metric.update(selector);
    return *evaluate(metric, result).value;
  };
  EXPECT_DOUBLE_EQ(peak("tension", json::object()), 2.0 * kForce);
  EXPECT_DOUBLE_EQ(peak("compression", json::object()), 3.0 * kForce);
  EXPECT_DOUBLE_EQ(peak("tension", {{"cycle", 1}}), kForce);
  EXPECT_DOUBLE_EQ(peak("compression", {{"cycle", 1}}), 1.2 * kForce);
  EXPECT_DOUBLE_EQ(peak("compression", {{"amplitude_dy", 10}}), 3.0 * kForce);
}

TEST(CompressionTensionRatio, IsPeakCompressionOverPeakTension) {
  const CyclicTestResult result = three_rectangles();
  const json ratio = {{"kind", "compression_tension_ratio"}};
  EXPECT_DOUBLE_EQ(*evaluate(ratio, result).value, 3.0 / 2.0); // over the run
  json first = ratio;
  first["cycle"] = 1;
  EXPECT_DOUBLE_EQ(*evaluate(first, result).value, 1.2);
  json at_ten = ratio;
  at_ten["amplitude_dy"] = 10;
  EXPECT_DOUBLE_EQ(*evaluate(at_ten, result).value, 2.0);
}

/// A monotonic bilinear branch in `sign` direction (+1 tension, -1 compression): elastic slope
/// K0 = Py / dy to Py, then slope alpha K0, points every dy / 10 up to 3 dy.
CyclicTestResult bilinear_branch(double sign, double alpha) {
  CyclicTestResult result;
  const double stiffness = kForce / kYieldDeform;
  for (int i = 0; i <= 30; ++i) {
    const double deformation = 0.1 * i * kYieldDeform;
    const double force = deformation <= kYieldDeform
                             ? stiffness * deformation
                             : kForce + alpha * stiffness * (deformation - kYieldDeform);
    result.steps.push_back(CyclicStep{i, i == 0 ? 0 : 1, sign * deformation, sign * force, 0.0, 1});
  }
  return result;
}

TEST(YieldForce, OffsetRuleOnABilinearBranchMatchesTheClosedForm) {
  // The offset line F = K0 (delta - o) meets F = Py + alpha K0 (delta - dy) at
  // F = Py + K0 o alpha / (1 - alpha) (Py = K0 dy). Offset o = 0.002 x 250 mm = 0.5 mm.
  const double offset = 0.002 * 250.0;
  const double stiffness = kForce / kYieldDeform;
  for (const double alpha : {0.0, 0.05, 0.1}) {
    const double expected = kForce + stiffness * offset * alpha / (1.0 - alpha);
    const json tension = {
        {"kind", "yield_force"}, {"direction", "tension"}, {"offset_core_strain", 0.002}};
    const MetricValue up = evaluate(tension, bilinear_branch(+1.0, alpha), 250.0);
    ASSERT_TRUE(up.value) << up.note;
    EXPECT_NEAR(*up.value, expected, 1e-9 * kForce) << "alpha " << alpha;
    json compression = tension;
    compression["direction"] = "compression";
    const MetricValue down = evaluate(compression, bilinear_branch(-1.0, alpha), 250.0);
    ASSERT_TRUE(down.value) << down.note;
    EXPECT_NEAR(*down.value, expected, 1e-9 * kForce) << "alpha " << alpha;
    // The tension rule finds nothing on a compression-only record.
    EXPECT_FALSE(evaluate(tension, bilinear_branch(-1.0, alpha), 250.0).value);
  }
}

TEST(FlagAndIndicator, ReadTheBraceIndicators) {
  CyclicTestResult result = three_rectangles();
  result.indicators.casing_failure = true;
  result.indicators.max_mortar_damage = 0.25;
  result.indicators.max_bearing_damage = 0.125;
  result.indicators.max_buckling_half_waves = 7;
  result.indicators.min_bearing_residual_strength = 0.375;
  result.indicators.min_fill_residual_strength = 0.0625;
  EXPECT_EQ(
      *evaluate({{"kind", "max_indicator"}, {"indicator", "min_bearing_residual_strength"}}, result)
           .value,
      0.375);
  EXPECT_EQ(
      *evaluate({{"kind", "max_indicator"}, {"indicator", "min_fill_residual_strength"}}, result)
           .value,
      0.0625);
  EXPECT_EQ(*evaluate({{"kind", "flag"}, {"flag", "casing_failure"}}, result).value, 1.0);
  EXPECT_EQ(*evaluate({{"kind", "flag"}, {"flag", "global_buckling"}}, result).value, 0.0);
  EXPECT_EQ(
      *evaluate({{"kind", "max_indicator"}, {"indicator", "max_mortar_damage"}}, result).value,
      0.25);
  EXPECT_EQ(
      *evaluate({{"kind", "max_indicator"}, {"indicator", "max_bearing_damage"}}, result).value,
      0.125);
  EXPECT_EQ(*evaluate({{"kind", "max_indicator"}, {"indicator", "max_buckling_half_waves"}}, result)
                 .value,
            7.0);
}

MetricSpec with_reference(double reference, Tolerance tolerance) {
  MetricSpec metric;
  metric.name = "m";
  metric.kind = "peak_force";
  metric.reference = reference;
  metric.tolerance = tolerance;
  return metric;
}

TEST(Judge, RelativeAndAbsoluteTolerances) {
  const MetricSpec relative = with_reference(100.0, {Tolerance::Kind::relative, 0.05});
  const auto passed = judge(relative, MetricValue{104.9, ""});
  EXPECT_EQ(passed.status, CheckStatus::pass);
  EXPECT_NEAR(*passed.error, 0.049, 1e-12);
  const auto failed = judge(relative, MetricValue{94.0, ""});
  EXPECT_EQ(failed.status, CheckStatus::fail);
  EXPECT_NEAR(*failed.error, -0.06, 1e-12);
  const MetricSpec absolute = with_reference(-10.0, {Tolerance::Kind::absolute, 2.0});
  EXPECT_EQ(judge(absolute, MetricValue{-8.5, ""}).status, CheckStatus::pass);
  EXPECT_NEAR(*judge(absolute, MetricValue{-8.5, ""}).error, 1.5, 1e-12);
  EXPECT_EQ(judge(absolute, MetricValue{-12.5, ""}).status, CheckStatus::fail);
}

TEST(Judge, BoundsFlagsMissingValuesAndReportedValues) {
  MetricSpec bounded;
  bounded.name = "damage";
  bounded.kind = "max_indicator";
  bounded.at_most = 0.1;
  EXPECT_EQ(judge(bounded, MetricValue{0.1, ""}).status, CheckStatus::pass);
  EXPECT_EQ(judge(bounded, MetricValue{0.11, ""}).status, CheckStatus::fail);
  bounded.at_least = 0.05;
  EXPECT_EQ(judge(bounded, MetricValue{0.01, ""}).status, CheckStatus::fail);

  MetricSpec flag;
  flag.name = "no buckling";
  flag.kind = "flag";
  flag.expected = false;
  EXPECT_EQ(judge(flag, MetricValue{0.0, ""}).status, CheckStatus::pass);
  EXPECT_EQ(judge(flag, MetricValue{1.0, ""}).status, CheckStatus::fail);

  // A check that cannot be made (no value) fails; a value without a check is reported.
  EXPECT_EQ(judge(bounded, MetricValue{std::nullopt, "cycle 9 was not completed"}).status,
            CheckStatus::fail);
  MetricSpec stated;
  stated.name = "beta";
  stated.kind = "compression_tension_ratio";
  EXPECT_EQ(judge(stated, MetricValue{1.1, ""}).status, CheckStatus::reported);
}

TEST(AutomaticChecks, CompletionAndEnergyBalanceAgainstOneInAMillion) {
  CyclicTestResult result = three_rectangles();
  result.energy_balance.external_work = 1000.0;
  result.energy_balance.gross_work = 1000.0;        // the balance's scale (EnergyBalance)
  result.energy_balance.dissipated = 1000.0 - 5e-4; // relative error 5e-7
  auto checks = brb::validation::automatic_checks(result);
  ASSERT_EQ(checks.size(), 3u);
  EXPECT_EQ(checks[0].status, CheckStatus::pass);
  EXPECT_EQ(checks[1].status, CheckStatus::pass);
  EXPECT_NEAR(*checks[1].value, 5e-7, 1e-12);
  EXPECT_EQ(checks[2].status, CheckStatus::reported);
  EXPECT_EQ(*checks[2].value, 0.0);
  // The integration misfit is part of the balance (external = stored + dissipated +
  // misfit + released) and is reported on its own, relative to the gross work.
  result.energy_balance.dissipated = 1000.0 - 0.1;
  result.energy_balance.integration_misfit = 0.1 - 5e-4;
  checks = brb::validation::automatic_checks(result);
  EXPECT_EQ(checks[1].status, CheckStatus::pass);
  EXPECT_NEAR(*checks[1].value, 5e-7, 1e-12);
  EXPECT_NEAR(*checks[2].value, 1e-4 - 5e-7, 1e-12);
  result.energy_balance.integration_misfit = 0.0;
  result.energy_balance.dissipated = 1000.0 - 2e-3; // 2e-6
  result.completed = false;
  result.stop_reason = "step 12: no convergence";
  checks = brb::validation::automatic_checks(result);
  EXPECT_EQ(checks[0].status, CheckStatus::fail);
  EXPECT_EQ(checks[0].note, "step 12: no convergence");
  EXPECT_EQ(checks[1].status, CheckStatus::fail);
}

} // namespace
