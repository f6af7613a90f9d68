// The hunt-and-fill tracer (Vamvatsikos & Cornell 2002, 2004) against synthetic "structures"
// whose collapse boundary is known, so every intensity it asks for can be computed by hand.
#include "brb/ida/hunt_and_fill.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace brb::ida {
namespace {

using Structure = std::function<bool(double)>; // collapsed at this intensity?

Structure collapses_above(double boundary) {
  return [boundary](double intensity) { return intensity > boundary; };
}

/// Runs the tracer to completion against `structure`.
HuntAndFill trace(const HuntFillSettings& settings, const Structure& structure) {
  HuntAndFill tracer(settings);
  while (const auto intensity = tracer.next_intensity())
    tracer.record(*intensity, structure(*intensity));
  return tracer;
}

std::vector<double> intensities(const HuntAndFill& tracer) {
  std::vector<double> values;
  for (const TracedRun& run : tracer.runs())
    values.push_back(run.intensity);
  return values;
}

void expect_intensities(const HuntAndFill& tracer, const std::vector<double>& expected) {
  const std::vector<double> actual = intensities(tracer);
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(actual[i], expected[i], 1e-12) << "run " << i;
}

bool all_distinct(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return std::adjacent_find(values.begin(), values.end()) == values.end();
}

// Defaults: first 0.1, step 0.1, growth 0.05, resolution 0.02, 12 runs. Collapse above 1.0.
// By hand: hunt IM_{k+1} = IM_k + 0.1 + 0.05 k: 0.1, 0.2, 0.35, 0.55, 0.8, 1.1 (collapses);
// bisect [0.8, 1.1]: 0.95 (survives), [0.95, 1.1]: 1.025 (collapses), [0.95, 1.025]: 0.9875
// (survives), [0.9875, 1.025] (width 0.0375): 1.00625 (collapses); [0.9875, 1.00625] has width
// 0.01875 <= 0.02: resolved after 10 runs. Fill the 2 runs left: the widest gaps between
// survivals 0.1 0.2 0.35 0.55 0.8 0.95 0.9875 are 0.55-0.8 (0.25) -> 0.675, then 0.35-0.55
// (0.2) -> 0.45.
TEST(HuntAndFill, HuntsBisectsAndFillsAsComputedByHand) {
  const HuntAndFill tracer = trace(HuntFillSettings{}, collapses_above(1.0));
  expect_intensities(tracer,
                     {0.1, 0.2, 0.35, 0.55, 0.8, 1.1, 0.95, 1.025, 0.9875, 1.00625, 0.675, 0.45});
  EXPECT_NEAR(*tracer.lowest_collapse(), 1.00625, 1e-12);
  EXPECT_NEAR(*tracer.highest_survival(), 0.9875, 1e-12);
  EXPECT_FALSE(tracer.next_intensity().has_value());
}

// For many boundaries and settings with budget to spare: the bracket holds the boundary and is
// no wider than the resolution, the budget holds, no intensity is asked twice, and the trace
// stops only when every gap between survivals is no wider than the resolution.
TEST(HuntAndFill, BracketsTheBoundaryWithinTheResolution) {
  const std::vector<HuntFillSettings> all_settings = {
      {0.1, 0.1, 0.05, 0.02, 40, 0.0},
      {0.05, 0.25, 0.0, 0.01, 40, 0.0},
      {0.2, 0.05, 0.1, 0.005, 40, 0.0},
  };
  for (const HuntFillSettings& settings : all_settings) {
    for (double boundary = 0.07; boundary < 3.0; boundary += 0.0931) {
      const HuntAndFill tracer = trace(settings, collapses_above(boundary));
      SCOPED_TRACE("boundary " + std::to_string(boundary));
      EXPECT_LE(tracer.runs().size(), static_cast<std::size_t>(settings.max_runs));
      EXPECT_TRUE(all_distinct(intensities(tracer)));
      ASSERT_TRUE(tracer.lowest_collapse().has_value());
      ASSERT_TRUE(tracer.highest_survival().has_value());
      EXPECT_GT(*tracer.lowest_collapse(), boundary);
      EXPECT_LE(*tracer.highest_survival(), boundary);
      EXPECT_LE(*tracer.lowest_collapse() - *tracer.highest_survival(), settings.resolution);
      if (tracer.runs().size() < static_cast<std::size_t>(settings.max_runs)) {
        std::vector<double> survivals;
        for (const TracedRun& run : tracer.runs()) {
          if (!run.collapsed)
            survivals.push_back(run.intensity);
        }
        std::sort(survivals.begin(), survivals.end());
        for (std::size_t i = 1; i < survivals.size(); ++i)
          EXPECT_LE(survivals[i] - survivals[i - 1], settings.resolution);
      }
    }
  }
}

// Once the bracket is resolved, each run is the midpoint of the widest gap between the
// survivals known at that moment (recomputed here; gaps within 1e-9 relative count as equal,
// the lowest of them first), so the filled gaps never widen.
TEST(HuntAndFill, FillsTheWidestGapFirst) {
  HuntFillSettings settings;
  settings.max_runs = 25;
  const HuntAndFill tracer = trace(settings, collapses_above(1.0));
  ASSERT_EQ(tracer.runs().size(), 25u);
  std::vector<double> survivals;
  double previous_gap = std::numeric_limits<double>::infinity();
  int fills = 0;
  for (std::size_t i = 0; i < tracer.runs().size(); ++i) {
    const TracedRun& run = tracer.runs()[i];
    if (i >= 10) { // runs 0..9 hunt and bisect (see the hand computation above)
      std::sort(survivals.begin(), survivals.end());
      double widest = 0.0, midpoint = 0.0;
      for (std::size_t k = 1; k < survivals.size(); ++k) {
        if (survivals[k] - survivals[k - 1] > widest * (1.0 + 1e-9)) {
          widest = survivals[k] - survivals[k - 1];
          midpoint = 0.5 * (survivals[k] + survivals[k - 1]);
        }
      }
      EXPECT_EQ(run.intensity, midpoint) << "run " << i;
      EXPECT_LE(widest, previous_gap * (1.0 + 1e-9));
      previous_gap = widest;
      ++fills;
    }
    if (!run.collapsed)
      survivals.push_back(run.intensity);
  }
  EXPECT_EQ(fills, 15);
  EXPECT_TRUE(all_distinct(intensities(tracer)));
}

// A tracer fed the same answers asks for bitwise the same intensities (a journal replay).
TEST(HuntAndFill, ReplayIsBitwiseIdentical) {
  const HuntAndFill first = trace(HuntFillSettings{}, collapses_above(0.777));
  std::vector<bool> answers;
  for (const TracedRun& run : first.runs())
    answers.push_back(run.collapsed);
  HuntAndFill replay(HuntFillSettings{});
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const auto intensity = replay.next_intensity();
    ASSERT_TRUE(intensity.has_value());
    EXPECT_EQ(std::bit_cast<std::uint64_t>(*intensity),
              std::bit_cast<std::uint64_t>(first.runs()[i].intensity));
    replay.record(*intensity, answers[i]);
  }
  EXPECT_FALSE(replay.next_intensity().has_value());
}

// Nothing collapses: the whole budget hunts, IM_k by the stated formula (by hand: 0.1, 0.2,
// 0.35, 0.55, 0.8, 1.1, 1.45, 1.85, 2.3, 2.8, 3.35, 3.95); the capacity is unknown.
TEST(HuntAndFill, NoCollapseWithinTheBudgetSpendsItHunting) {
  const HuntAndFill tracer = trace(HuntFillSettings{}, [](double) { return false; });
  expect_intensities(tracer, {0.1, 0.2, 0.35, 0.55, 0.8, 1.1, 1.45, 1.85, 2.3, 2.8, 3.35, 3.95});
  EXPECT_FALSE(tracer.lowest_collapse().has_value());
  EXPECT_NEAR(*tracer.highest_survival(), 3.95, 1e-12);
}

// With max_intensity 1.0 the hunt stops at the limit itself (1.1 is capped to 1.0) and the
// rest of the budget fills: survivals 0.1 0.2 0.35 0.55 0.8 1.0 have gaps 0.1 0.15 0.2 0.25 0.2
// -> 0.675; then 0.35-0.55 -> 0.45 (the lower of the two 0.2 gaps); then 0.8-1.0 -> 0.9; then
// the 0.15 gap 0.2-0.35 -> 0.275; then the 0.125 gaps from below: 0.55-0.675 -> 0.6125,
// 0.675-0.8 -> 0.7375.
TEST(HuntAndFill, MaxIntensityCapsTheHunt) {
  HuntFillSettings settings;
  settings.max_intensity = 1.0;
  const HuntAndFill tracer = trace(settings, [](double) { return false; });
  expect_intensities(tracer,
                     {0.1, 0.2, 0.35, 0.55, 0.8, 1.0, 0.675, 0.45, 0.9, 0.275, 0.6125, 0.7375});
  for (const TracedRun& run : tracer.runs())
    EXPECT_LE(run.intensity, 1.0);
}

// The first run collapses (boundary 0.03 below the first intensity 0.1): bisection between 0
// and it halves the intensity until a run survives: 0.1 C, 0.05 C, 0.025 S, then [0.025, 0.05]
// (width 0.025): 0.0375 C; [0.025, 0.0375] has width 0.0125: resolved. One survival, no gap to
// fill: the trace ends after 4 runs, inside the budget.
TEST(HuntAndFill, FirstRunCollapsingHalvesUntilASurvival) {
  const HuntAndFill tracer = trace(HuntFillSettings{}, collapses_above(0.03));
  expect_intensities(tracer, {0.1, 0.05, 0.025, 0.0375});
  EXPECT_NEAR(*tracer.lowest_collapse(), 0.0375, 1e-15);
  EXPECT_NEAR(*tracer.highest_survival(), 0.025, 1e-15);
}

// Every run collapses down to the resolution: 0.1, 0.05, 0.025, 0.0125, then [0, 0.0125] is
// resolved; no survival is known.
TEST(HuntAndFill, CapacityBelowTheResolutionLeavesNoSurvival) {
  const HuntAndFill tracer = trace(HuntFillSettings{}, collapses_above(0.001));
  expect_intensities(tracer, {0.1, 0.05, 0.025, 0.0125});
  EXPECT_FALSE(tracer.highest_survival().has_value());
  EXPECT_NEAR(*tracer.lowest_collapse(), 0.0125, 1e-15);
}

// Collapse in a window [0.5, 0.7] and above 2.0, survival between ("resurrection"): the hunt
// first collapses at 0.55, inside the window; bisection [0.35, 0.55]: 0.45 S, 0.5 C,
// 0.475 S, 0.4875 S -> the bracket [0.4875, 0.5] holds the window's lower edge.
TEST(HuntAndFill, CollapseWindowIsBracketedAtItsLowerEdge) {
  const Structure window = [](double im) { return (im >= 0.5 && im <= 0.7) || im > 2.0; };
  const HuntAndFill tracer = trace(HuntFillSettings{}, window);
  ASSERT_GE(tracer.runs().size(), 8u);
  const std::vector<double> runs = intensities(tracer);
  const std::vector<double> expected = {0.1, 0.2, 0.35, 0.55, 0.45, 0.5, 0.475, 0.4875};
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(runs[i], expected[i], 1e-12) << "run " << i;
  EXPECT_NEAR(*tracer.lowest_collapse(), 0.5, 1e-12);
  EXPECT_NEAR(*tracer.highest_survival(), 0.4875, 1e-12);
}

// A fill run that lands in a collapse window below the bracket found by the hunt (collapse in
// [0.25, 0.3] and above 1.0): the bracket moves to the first collapse above the highest
// survival below it and is bisected again before filling resumes. By hand (budget 30): runs
// 1-10 as in the first test; fills 0.675, 0.45, then the first 0.15 gap 0.2-0.35 -> 0.275
// collapses; bisection [0.2, 0.275]: 0.2375 S, 0.25625 C, width 0.01875: resolved.
TEST(HuntAndFill, FillFindingALowerCollapseReopensTheBracket) {
  const Structure window = [](double im) { return (im >= 0.25 && im <= 0.3) || im > 1.0; };
  HuntFillSettings settings;
  settings.max_runs = 30;
  const HuntAndFill tracer = trace(settings, window);
  const std::vector<double> runs = intensities(tracer);
  ASSERT_GE(runs.size(), 15u);
  const std::vector<double> expected = {0.675, 0.45, 0.275, 0.2375, 0.25625};
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(runs[10 + i], expected[i], 1e-12) << "run " << 10 + i;
  EXPECT_NEAR(*tracer.lowest_collapse(), 0.25625, 1e-12);
  EXPECT_NEAR(*tracer.highest_survival(), 0.2375, 1e-12);
  // The rest of the budget fills below the new flatline only.
  for (std::size_t i = 15; i < runs.size(); ++i)
    EXPECT_LT(runs[i], 0.25625);
  EXPECT_TRUE(all_distinct(runs));
  EXPECT_FALSE(tracer.next_intensity().has_value());
}

TEST(HuntAndFill, RecordingAnotherIntensityThrows) {
  HuntAndFill tracer(HuntFillSettings{});
  const double asked = *tracer.next_intensity();
  EXPECT_THROW(tracer.record(0.2, false), std::logic_error);
  EXPECT_THROW(tracer.record(std::nextafter(asked, 1.0), false), std::logic_error);
  EXPECT_TRUE(tracer.runs().empty());
  tracer.record(asked, false);
  EXPECT_EQ(tracer.runs().size(), 1u);

  HuntFillSettings one_run;
  one_run.max_runs = 1;
  HuntAndFill single(one_run);
  single.record(*single.next_intensity(), true);
  EXPECT_FALSE(single.next_intensity().has_value());
  EXPECT_THROW(single.record(0.05, false), std::logic_error);
}

void expect_rejected(const HuntFillSettings& settings, const std::string& field) {
  try {
    HuntAndFill tracer(settings);
    ADD_FAILURE() << "settings accepted, expected a complaint about " << field;
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find(field), std::string::npos) << error.what();
  }
}

TEST(HuntAndFill, SettingsOutOfRangeThrowNamingTheField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto with = [](auto change) {
    HuntFillSettings settings;
    change(settings);
    return settings;
  };
  expect_rejected(with([](HuntFillSettings& s) { s.first_intensity = 0.0; }), "first_intensity");
  expect_rejected(with([&](HuntFillSettings& s) { s.first_intensity = nan; }), "first_intensity");
  expect_rejected(with([](HuntFillSettings& s) { s.step = -0.1; }), "step");
  expect_rejected(with([](HuntFillSettings& s) { s.step = 0.0; }), "step");
  expect_rejected(with([](HuntFillSettings& s) { s.step_growth = -0.01; }), "step_growth");
  expect_rejected(with([](HuntFillSettings& s) { s.resolution = 0.0; }), "resolution");
  expect_rejected(with([](HuntFillSettings& s) { s.max_runs = 0; }), "max_runs");
  expect_rejected(with([](HuntFillSettings& s) { s.max_intensity = -1.0; }), "max_intensity");
  expect_rejected(with([](HuntFillSettings& s) { s.max_intensity = 0.05; }), "max_intensity");
  EXPECT_NO_THROW(HuntAndFill(with([](HuntFillSettings& s) { s.max_intensity = 0.1; })));
}

} // namespace
} // namespace brb::ida
