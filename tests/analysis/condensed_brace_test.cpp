// The cyclic test of the condensed brace (analysis/condensed_brace.hpp) against the cyclic test
// of the expanded brace model: the same equations, so the same hysteresis to the solvers'
// tolerance (reference: run_cyclic_test on build_brace_model, an independent assembly of the
// same brace). Girona bar D3 with 4 core elements in its casing, through cycles at 0.5, 1 and
// 2 dy in steps of dy / 10.
#include "brb/analysis/condensed_brace.hpp"
#include "brb/io/protocol.hpp"
#include "brb/model/brace_model.hpp"

#include "support/brace_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace brb::analysis {
namespace {

TEST(CondensedBrace, RestrainedCoreHasTheExpandedModelsHysteresis) {
  const model::BraceSpec spec = test::girona_d3_restrained(4);
  // Both converged well below the compared difference (as tests/slow/
  // brb_element_restrained_test.cpp): at the default tolerances the residual floor, 1e-14 of
  // the model's size times its stiffest element, is about 0.25 N here, and the two runs then
  // differ by up to 0.35 N of 41.6 kN (measured).
  NewtonSettings tight;
  tight.relative_force_tolerance = 1e-12;
  tight.position_round_off = 1e-16;
  model::BraceModel expanded = model::build_brace_model(spec);
  const double dy = expanded.yield_deformation;
  const io::LoadingProtocol protocol =
      io::cyclic_protocol("test", {{0.5 * dy, 1}, {dy, 1}, {2.0 * dy, 1}}, dy / 10.0);
  const CyclicTestResult reference = run_cyclic_test(expanded, protocol.deformation, protocol.cycle,
                                                     protocol.cycle_amplitude, tight);
  ASSERT_TRUE(reference.completed) << reference.stop_reason;

  const auto condensed = build_condensed_brace_model(spec, tight);
  EXPECT_EQ(condensed->element->internal_brace().yield_deformation, dy);
  const CyclicTestResult result = run_condensed_cyclic_test(
      *condensed, protocol.deformation, protocol.cycle, protocol.cycle_amplitude, tight);
  ASSERT_TRUE(result.completed) << result.stop_reason;
  ASSERT_EQ(result.steps.size(), reference.steps.size());
  const double force_scale = std::abs(reference.max_compression) + reference.max_tension;
  for (std::size_t k = 0; k < result.steps.size(); ++k) {
    EXPECT_EQ(result.steps[k].cycle, reference.steps[k].cycle) << "step " << k;
    EXPECT_NEAR(result.steps[k].deformation, reference.steps[k].deformation, 1e-12);
    EXPECT_NEAR(result.steps[k].force, reference.steps[k].force, 1e-6 * force_scale)
        << "step " << k;
  }
  ASSERT_EQ(result.cycles.size(), 3U);
  ASSERT_EQ(result.cycles.size(), reference.cycles.size());
  for (std::size_t c = 0; c < result.cycles.size(); ++c) {
    EXPECT_NEAR(result.cycles[c].energy, reference.cycles[c].energy,
                1e-6 * std::abs(reference.cycles.back().energy))
        << "cycle " << c + 1;
    EXPECT_EQ(result.cycles[c].amplitude, reference.cycles[c].amplitude);
  }
  // the 2 dy cycle yields: a loop, not an elastic line
  EXPECT_GT(result.cycles.back().energy, 0.1 * dy * reference.max_tension);
  EXPECT_GT(result.iterations, 0);
}

} // namespace
} // namespace brb::analysis
