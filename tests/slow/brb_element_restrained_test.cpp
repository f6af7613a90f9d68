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
  model::BraceSpec spec = test::girona_d3_bare_core(8, false);
  model::CasingSpec casing;
  casing.tube.shape = model::SectionShape::circular_tube;
  casing.tube.diameter = 115.0;
  casing.tube.wall = 3.0;
  casing.tube.fibers_a = 1;
  casing.tube.fibers_b = 12;
  casing.tube_steel = spec.steel;
  casing.mortar = {17520.0, 0.2, 50.0, 5.0, 0.1};
  casing.fill_fibers_a = 1;
  casing.fill_fibers_b = 12;
  casing.gap_y = casing.gap_z = 0.5;
  spec.casing = casing;
  const test::Comparison comparison = test::compare_condensed_and_expanded(spec, {0.5, 1.0});
  ASSERT_GT(comparison.steps, 30u);
  EXPECT_LT(comparison.largest_difference, 1e-6 * comparison.largest_force)
      << comparison.largest_difference << " N of " << comparison.largest_force << " N";
}

} // namespace
} // namespace brb::analysis
