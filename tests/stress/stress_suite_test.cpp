// ctest -L stress: the short numerical stress suite of issue 9, one test per case group.
// Acceptance per case (the issue): no NaN in any output, completed or an explicit failure
// reason, energy-balance error under 1 % of the input work. The inputs are the reference
// brace (examples/braces/girona_D3_restrained.json), brbf3 and the shared Rinaldi228 record,
// the defaults of `brb bench stress`.
#include "brb/study/stress_run.hpp"
#include "brb/study/stress_suite.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

namespace brb::study {
namespace {

namespace fs = std::filesystem;

StressSuiteInputs reference_inputs() {
  return {fs::path(BRB_SOURCE_DIR) / "examples/braces/girona_D3_restrained.json",
          fs::path(BRB_SOURCE_DIR) / "frames/brbf3/model.json",
          fs::path(BRB_SHARED_DIR) / "data/ground_motions/Rinaldi228.AT2"};
}

/// The short suite's cases of one group.
std::vector<StressCase> short_cases(StressGroup group) {
  std::vector<StressCase> selected;
  for (StressCase& stress_case : make_stress_suite(reference_inputs(), {false, 1})) {
    if (stress_case.group == group)
      selected.push_back(std::move(stress_case));
  }
  return selected;
}

/// Runs the cases and checks the acceptance of each; returns the results.
std::vector<StressResult> run_and_check(const std::vector<StressCase>& cases) {
  EXPECT_FALSE(cases.empty());
  std::vector<StressResult> results;
  for (const StressCase& stress_case : cases) {
    results.push_back(run_stress_case(stress_case));
    const StressResult& result = results.back();
    SCOPED_TRACE(result.name + ": " + result.outcome + " (" + result.notes + ")");
    EXPECT_EQ(result.nan_count, 0);
    EXPECT_TRUE(result.completed || !result.failure_reason.empty());
    EXPECT_LT(result.energy_error, kEnergyErrorLimit);
    EXPECT_TRUE(result.acceptable()) << result.acceptance_failure();
    // Every converged step was timed, and a run that did not fail did every step.
    EXPECT_EQ(result.step_wall_times.size(), static_cast<std::size_t>(result.steps));
    if (result.completed && !result.collapsed) {
      EXPECT_EQ(result.steps, result.planned_steps);
    }
  }
  return results;
}

TEST(StressSuite, RandomHistoriesUpTo20Dy) {
  const std::vector<StressResult> results = run_and_check(short_cases(StressGroup::random_history));
  // Truss and full braces both stressed.
  EXPECT_TRUE(std::any_of(results.begin(), results.end(), [](const StressResult& r) {
    return r.name.find("/full") != std::string::npos;
  }));
}

TEST(StressSuite, MonotonicCompressionTo10PercentCoreStrain) {
  for (const StressResult& result :
       run_and_check(short_cases(StressGroup::monotonic_compression))) {
    // The truss cannot fail to follow a monotonic path: it must get to the end.
    if (result.name.find("/truss/") != std::string::npos) {
      EXPECT_TRUE(result.completed) << result.failure_reason;
    }
  }
}

TEST(StressSuite, StepSizesFromOneHundredthToTenTimesTheDefault) {
  const std::vector<StressCase> cases = short_cases(StressGroup::step_size);
  const std::vector<StressResult> results = run_and_check(cases);
  // The truss's steel law is integrated exactly for any step (closed-form return map), so
  // its energy balance holds at every step size.
  for (const StressResult& result : results) {
    if (result.name.find("/truss/") != std::string::npos) {
      EXPECT_TRUE(result.completed) << result.name << ": " << result.failure_reason;
    }
  }
}

TEST(StressSuite, FrameAtAndBeyondItsCollapseIntensity) {
  const std::vector<StressResult> results = run_and_check(short_cases(StressGroup::frame_collapse));
  const std::size_t at_limit = frame_collapse_scales(false).size();
  ASSERT_EQ(results.size(), at_limit + beyond_collapse_scales(false).size());
  // The scales bracket the collapse: the record as it is does not collapse brbf3, the
  // largest scale does (drift > 10 %, frames/brbf3 analysis.drift_limit).
  EXPECT_FALSE(results.front().collapsed) << results.front().notes;
  EXPECT_LT(results.front().peak_drift, 0.10);
  EXPECT_TRUE(results[at_limit - 1].collapsed) << results[at_limit - 1].notes;
  EXPECT_GT(results[at_limit - 1].peak_drift, 0.10);
  // Beyond: the limit raised, the solver is driven on past 10 % drift.
  for (std::size_t k = at_limit; k < results.size(); ++k)
    EXPECT_GT(results[k].peak_drift, 0.10) << results[k].name << ": " << results[k].notes;
}

TEST(StressSuite, NearSingularBraces) {
  run_and_check(short_cases(StressGroup::near_singular));
}

} // namespace
} // namespace brb::study
