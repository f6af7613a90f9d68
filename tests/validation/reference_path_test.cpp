// Matching a reference sampled its own way to the protocol's points along the deformation
// travel (reference_path.hpp), and the failure mode and cycle of a model against a
// reference's (failure_mode.hpp), on histories whose answers follow from the definitions.
#include "brb/validation/failure_mode.hpp"
#include "brb/validation/reference_path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using brb::analysis::CyclicStep;
using brb::analysis::CyclicTestResult;
using brb::analysis::ElementHistoryPoint;
using brb::validation::compare_failures;
using brb::validation::deformation_travel;
using brb::validation::FailureEvent;
using brb::validation::FailureMode;
using brb::validation::match_along_path;
using brb::validation::model_failure;

/// A triangle wave 0 -> +a -> -a -> +a -> 0 in steps of `step` (mm).
std::vector<double> triangle(double amplitude, double step) {
  std::vector<double> points{0.0};
  for (const double target : {amplitude, -amplitude, amplitude, 0.0}) {
    while (std::abs(target - points.back()) > 1e-12) {
      const double move = std::min(step, std::abs(target - points.back()));
      points.push_back(points.back() + std::copysign(move, target - points.back()));
    }
  }
  return points;
}

TEST(DeformationTravel, SumsTheAbsoluteIncrements) {
  // Reference (definition): 0 -> 2 -> -1 -> 0 travels 2 + 3 + 1.
  EXPECT_EQ(deformation_travel(std::vector<double>{0.0, 2.0, -1.0, 0.0}),
            (std::vector<double>{0.0, 2.0, 5.0, 6.0}));
}

TEST(MatchAlongPath, SameSamplingGivesTheReferencesOwnValues) {
  // The reference made on the protocol's own points: every value comes back bit for bit.
  const std::vector<double> path = triangle(3.0, 0.3);
  std::vector<double> force;
  for (std::size_t k = 0; k < path.size(); ++k)
    force.push_back(std::sin(0.37 * static_cast<double>(k)) * 1000.0 / 3.0);
  const auto match = match_along_path(path, path, force);
  EXPECT_EQ(match.matched, path.size());
  EXPECT_EQ(match.force, force);
  EXPECT_EQ(match.largest_deformation_difference, 0.0);
}

TEST(MatchAlongPath, InterpolatesLinearlyInTravelOnTheRightExcursion) {
  // Reference (linear interpolation is exact for a linear function): a reference sampled
  // every 0.5 mm whose force is 7 s + 100 (s the travel) gives 7 s + 100 at the protocol's
  // points, sampled every 0.2 mm. Deformation 0 is passed three times (s = 0, 6, 12 mm for
  // a = 3): each crossing takes its own excursion's force.
  const std::vector<double> protocol = triangle(3.0, 0.2);
  const std::vector<double> reference = triangle(3.0, 0.5);
  const std::vector<double> reference_travel = deformation_travel(reference);
  std::vector<double> force;
  for (const double s : reference_travel)
    force.push_back(7.0 * s + 100.0);
  const auto match = match_along_path(protocol, reference, force);
  const std::vector<double> travel = deformation_travel(protocol);
  ASSERT_EQ(match.matched, protocol.size());
  for (std::size_t k = 0; k < protocol.size(); ++k)
    EXPECT_NEAR(match.force[k], 7.0 * travel[k] + 100.0, 1e-9) << "point " << k;
  EXPECT_LT(match.largest_deformation_difference, 1e-12);
}

TEST(MatchAlongPath, AReferenceThatStopsEarlyIsComparedOverWhatItHas) {
  const std::vector<double> protocol = triangle(3.0, 0.5);
  const std::vector<double> reference(protocol.begin(), protocol.begin() + 9); // 0..3..1
  const std::vector<double> force(reference.size(), 5.0);
  const auto match = match_along_path(protocol, reference, force);
  EXPECT_EQ(match.matched, 9u);
  EXPECT_EQ(match.force[8], 5.0);
  EXPECT_TRUE(std::isnan(match.force[9]));
  EXPECT_TRUE(std::isnan(match.force.back()));
}

TEST(MatchAlongPath, MeasuresHowFarAnotherPathIs) {
  // A reference of amplitude 2 against a protocol of amplitude 3, both in 0.5 mm steps. By
  // hand, at travel s in [0, 12] (the reference's length): the protocol is at s, 6 - s,
  // s - 12 on its legs [0, 3], [3, 9], [9, 15]; the reference at s, 4 - s, s - 8, 12 - s on
  // [0, 2], [2, 6], [6, 10], [10, 12]. The gap is largest, 4 mm, on s in [9, 10], first at
  // s = 9 where the protocol is at -3 mm. Checked also point by point against the
  // reference's own points (every 0.5 mm of travel).
  const std::vector<double> protocol = triangle(3.0, 0.5);
  const std::vector<double> reference = triangle(2.0, 0.5);
  const std::vector<double> force(reference.size(), 1.0);
  const auto match = match_along_path(protocol, reference, force);
  const std::vector<double> travel = deformation_travel(protocol);
  const std::vector<double> reference_travel = deformation_travel(reference);
  double largest = 0.0;
  for (std::size_t k = 0; k < match.matched; ++k) {
    // the reference's deformation at travel s: points lie every 0.5 mm of travel
    const auto j = static_cast<std::size_t>(std::lround(travel[k] / 0.5));
    ASSERT_NEAR(reference_travel[j], travel[k], 1e-12);
    largest = std::max(largest, std::abs(reference[j] - protocol[k]));
  }
  EXPECT_NEAR(match.largest_deformation_difference, largest, 1e-12);
  EXPECT_NEAR(largest, 4.0, 1e-12);
  EXPECT_NEAR(travel[match.largest_difference_point], 9.0, 1e-12);
  EXPECT_NEAR(protocol[match.largest_difference_point], -3.0, 1e-12);
}

TEST(MatchAlongPath, RefusesBadSeries) {
  const std::vector<double> one{0.0};
  EXPECT_THROW(match_along_path(one, one, one), std::invalid_argument);
  const std::vector<double> two{0.0, 1.0};
  EXPECT_THROW(match_along_path(two, two, one), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------

/// A run of `cycles` cycles of 4 steps each whose flags are raised as `raise` says (step at
/// which each flag goes up; -1 never), with the step history recorded.
CyclicTestResult flagged_run(int cycles, int fracture_step, int casing_step, int buckling_step) {
  CyclicTestResult result;
  result.steps.push_back(CyclicStep{0, 0, 0.0, 0.0, 0.0, 0});
  for (int c = 1; c <= cycles; ++c) {
    for (int i = 0; i < 4; ++i) {
      const int step = static_cast<int>(result.steps.size());
      result.steps.push_back(CyclicStep{step, c, 0.0, 0.0, 0.0, 1});
    }
  }
  for (const CyclicStep& step : result.steps) {
    ElementHistoryPoint point;
    point.step = step.step;
    point.indicators.core_fracture = fracture_step >= 0 && step.step >= fracture_step;
    point.indicators.casing_failure = casing_step >= 0 && step.step >= casing_step;
    point.indicators.global_buckling = buckling_step >= 0 && step.step >= buckling_step;
    result.history.push_back(point);
  }
  result.indicators = result.history.back().indicators;
  return result;
}

TEST(ModelFailure, TheFirstFlagRaisedAndTheCycleOfItsStep) {
  // Steps 1-4 are cycle 1, 5-8 cycle 2, 9-12 cycle 3, ...
  const auto casing_then_buckling = model_failure(flagged_run(5, -1, 10, 14));
  ASSERT_TRUE(casing_then_buckling);
  EXPECT_EQ(casing_then_buckling->mode, FailureMode::casing_failure);
  EXPECT_EQ(casing_then_buckling->cycle, 3);
  const auto buckling_first = model_failure(flagged_run(5, 18, -1, 5));
  ASSERT_TRUE(buckling_first);
  EXPECT_EQ(buckling_first->mode, FailureMode::global_buckling);
  EXPECT_EQ(buckling_first->cycle, 2);
  const auto none = model_failure(flagged_run(5, -1, -1, -1));
  ASSERT_TRUE(none);
  EXPECT_EQ(none->mode, FailureMode::none);
  // A raised flag without the history: the cycle is not known.
  CyclicTestResult without_history = flagged_run(5, 3, -1, -1);
  without_history.history.clear();
  EXPECT_FALSE(model_failure(without_history));
}

TEST(CompareFailures, SameModeWithinTheCycleTolerance) {
  const FailureEvent model{FailureMode::casing_failure, 4};
  EXPECT_TRUE(compare_failures(model, {FailureMode::casing_failure, 4}, 1).agrees);
  EXPECT_TRUE(compare_failures(model, {FailureMode::casing_failure, 3}, 1).agrees);
  EXPECT_TRUE(compare_failures(model, {FailureMode::casing_failure, 5}, 1).agrees);
  EXPECT_FALSE(compare_failures(model, {FailureMode::casing_failure, 6}, 1).agrees);
  EXPECT_FALSE(compare_failures(model, {FailureMode::casing_failure, 2}, 1).agrees);
  EXPECT_TRUE(compare_failures(model, {FailureMode::casing_failure, 6}, 2).agrees);
  EXPECT_FALSE(compare_failures(model, {FailureMode::global_buckling, 4}, 1).agrees);
  EXPECT_FALSE(compare_failures(model, {FailureMode::none, 0}, 1).agrees);
  EXPECT_TRUE(compare_failures({}, {}, 0).agrees);
  EXPECT_EQ(compare_failures(model, {FailureMode::casing_failure, 6}, 1).description,
            "model casing_failure in cycle 4, reference casing_failure in cycle 6");
}

} // namespace
