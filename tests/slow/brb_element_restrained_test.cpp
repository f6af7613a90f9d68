// The condensed BRB element against the expanded brace model with a casing (slow: about
// 10 s): the Girona D3 core (8 elements) in its tube and mortar, cycles at 0.5 and 1 dy.
#include "support/brace_fixtures.hpp"
#include "support/brb_element_fixtures.hpp"

#include <gtest/gtest.h>

namespace brb::analysis {
namespace {

TEST(BRBElementCondensed, AgreesWithTheExpandedModelOnARestrainedCoreAtSmallAmplitude) {
  // The core in its casing (gap 0.5 mm, mortar bearing, friction, stopper), cycles at 0.5
  // and 1 dy: the core bows into the gap and bears on the mortar in compression.
  // (coarser fibers than the restrained tests: the comparison needs no resolution)
  model::BraceSpec spec = test::girona_d3_restrained(8);
  spec.casing->tube.fibers_b = 12;
  spec.casing->fill_fibers_a = 1;
  spec.casing->fill_fibers_b = 12;
  const test::Comparison comparison = test::compare_condensed_and_expanded(spec, {0.5, 1.0});
  ASSERT_GT(comparison.steps, 30u);
  EXPECT_LT(comparison.largest_difference, 1e-6 * comparison.largest_force)
      << comparison.largest_difference << " N of " << comparison.largest_force << " N";
}

} // namespace
} // namespace brb::analysis
