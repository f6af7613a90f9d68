// The core's lateral (Poisson) expansion in the casing contact, seen on a whole brace
// (issue 4): a straight restrained core in compression grows sideways by 0.5 |eps| h / 2 per
// side; once that closes the clearance the mortar confines it, and friction on the confined
// core raises the compression force (the compression overstrength beta).
#include "brb/analysis/brb_element.hpp"
#include "brb/analysis/cyclic_test.hpp"
#include "brb/io/protocol.hpp"

#include "support/brace_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

namespace brb::analysis {
namespace {

struct ExpansionRun {
  CyclicTestResult result;
  double largest_normal_force = 0.0; ///< over the links and the steps (N)
};

/// The Girona D3 brace in its casing (4 core elements), perfectly straight (no bow: without
/// the expansion nothing presses the core on the mortar), one cycle at 1 dy and one at 4 dy,
/// steps of `step_in_dy` dy.
ExpansionRun straight_brace_cycles(double gap, double core_expansion, double step_in_dy) {
  model::BraceSpec spec = test::girona_d3_restrained(4);
  spec.imperfection.amplitude = 0.0;
  spec.casing->gap_y = spec.casing->gap_z = gap;
  spec.casing->core_expansion = core_expansion;
  model::BraceModel brace = model::build_brace_model(spec);
  const double dy = brace.yield_deformation;
  const io::LoadingProtocol protocol =
      io::cyclic_protocol("expansion", {{1.0 * dy, 1}, {4.0 * dy, 1}}, step_in_dy * dy);
  // point by point, to read the links' normal forces at every step
  CyclicTest test(brace);
  ExpansionRun run;
  for (std::size_t k = 1; k < protocol.deformation.size(); ++k) {
    if (!test.follow(std::span(protocol.deformation).subspan(k, 1),
                     std::span(protocol.cycle).subspan(k, 1), protocol.cycle_amplitude))
      break;
    for (const element::CasingContact* contact : brace.casing->contacts)
      run.largest_normal_force = std::max(run.largest_normal_force, contact->normal_force());
  }
  run.result = test.result();
  EXPECT_TRUE(run.result.completed) << run.result.stop_reason;
  return run;
}

/// The links' node lists of a brace's casing, as built.
std::vector<std::vector<int>> link_nodes(const model::CasingModel& casing) {
  std::vector<std::vector<int>> all;
  for (const element::CasingContact* contact : casing.contacts)
    all.emplace_back(contact->nodes().begin(), contact->nodes().end());
  return all;
}

TEST(CoreExpansion, EachLinkHoldsItsStationsNeighbourCoreNodesInBothBraceForms) {
  // Each link: core node, casing node, then the core nodes before and after the station (at
  // an end station only the next or the previous one: the chord starts at the station); the
  // condensed BRBElement's internal brace has the same links; core_expansion 0: two nodes.
  model::BraceSpec spec = test::girona_d3_restrained(4);
  spec.casing->core_expansion = 0.5;
  const model::BraceModel brace = model::build_brace_model(spec);
  const model::CasingModel& casing = *brace.casing;
  const std::vector<int>& core = casing.core_nodes;
  const std::size_t stations = core.size();
  ASSERT_EQ(stations, 5u);
  const auto links = link_nodes(casing);
  for (std::size_t n = 0; n < stations; ++n) {
    std::vector<int> expected{core[n], casing.nodes[n]};
    if (n > 0)
      expected.push_back(core[n - 1]);
    if (n + 1 < stations)
      expected.push_back(core[n + 1]);
    EXPECT_EQ(links[n], expected) << "station " << n;
  }
  const analysis::BRBElement condensed({0, 1}, element::Vector3::Zero(),
                                       element::Vector3(spec.total_length(), 0.0, 0.0), spec,
                                       std::nullopt, {}, {});
  EXPECT_EQ(link_nodes(*condensed.internal_brace().casing), links);
  model::BraceSpec off = spec;
  off.casing->core_expansion = 0.0;
  for (const auto& nodes : link_nodes(*model::build_brace_model(off).casing))
    EXPECT_EQ(nodes.size(), 2u);
}

TEST(CoreExpansion, ConfinementRaisesTheCompressionPeakWhenItClosesTheGap) {
  // Theory: at 4 dy the core's strain is about 4 fy / E = 0.0052, so it grows by
  // 0.25 x 0.0052 x 22 mm = 0.029 mm per side. A 0.01 mm clearance closes: both faces bear
  // on every link, and friction (kappa 0.1) between core and casing adds to the compression
  // force. Without the expansion the straight core never touches the mortar. Steps of
  // dy / 8: the energy balance's trapezoidal work is first order where the faces close and
  // friction slips within a step (its error 2.3e-3 at dy / 4 steps, 9.6e-5 at dy / 8).
  const ExpansionRun with = straight_brace_cycles(0.01, 0.5, 0.125);
  const ExpansionRun without = straight_brace_cycles(0.01, 0.0, 0.125);
  ASSERT_TRUE(with.result.completed && without.result.completed);
  EXPECT_GT(with.largest_normal_force, 0.0);
  EXPECT_EQ(without.largest_normal_force, 0.0);
  EXPECT_LT(with.result.max_compression, without.result.max_compression); // negative: larger
  // tension shrinks the core: the tension peak moves far less than the compression peak
  const double compression_gain = without.result.max_compression - with.result.max_compression;
  const double tension_change = std::abs(with.result.max_tension - without.result.max_tension);
  EXPECT_GT(compression_gain, 5.0 * tension_change);
  EXPECT_LT(std::abs(with.result.energy_balance.relative_error()), 1e-3);
}

TEST(CoreExpansion, ExpansionThatNeverClosesTheGapChangesNothing) {
  // Theory: with the 0.5 mm clearance of the fixture the expansion at 4 dy (0.029 mm) leaves
  // every face open: the links add exactly nothing. Not bit for bit: the four-node links
  // change the stiffness matrix's sparsity pattern and with it the order of the linear
  // solver's sums (last-bit differences, 4e-11 N at 50 kN), so round-off (1e-12 of the yield
  // force) is the tolerance.
  const ExpansionRun with = straight_brace_cycles(0.5, 0.5, 0.25);
  const ExpansionRun without = straight_brace_cycles(0.5, 0.0, 0.25);
  ASSERT_EQ(with.result.steps.size(), without.result.steps.size());
  EXPECT_EQ(with.largest_normal_force, 0.0);
  const double yield_force = 275.0 * std::numbers::pi * 11.0 * 11.0;
  for (std::size_t k = 0; k < with.result.steps.size(); ++k) {
    ASSERT_NEAR(with.result.steps[k].force, without.result.steps[k].force, 1e-12 * yield_force)
        << "step " << k;
  }
}

} // namespace
} // namespace brb::analysis
