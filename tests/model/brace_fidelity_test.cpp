// The `auto` fidelity rule (model/brace_fidelity.hpp): its Euler load against the closed-form
// flexural rigidity of concentric discs and rings, and each branch of the rule.
#include "brb/model/brace_fidelity.hpp"

#include "support/brace_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace brb::model {
namespace {

/// E I of a round core in a circular tube with its mortar ring (closed form, pi d^4 / 64).
double closed_form_rigidity(const BraceSpec& spec) {
  const auto disc = [](double diameter) { return std::numbers::pi * std::pow(diameter, 4) / 64.0; };
  const CasingSpec& casing = *spec.casing;
  const double inner = casing.tube.diameter - 2.0 * casing.tube.wall;
  const double opening = spec.core_section.diameter + 2.0 * casing.gap_y;
  return spec.steel.youngs_modulus * disc(spec.core_section.diameter) +
         casing.tube_steel.youngs_modulus * (disc(casing.tube.diameter) - disc(inner)) +
         casing.mortar.youngs_modulus * (disc(inner) - disc(opening));
}

TEST(AutoFidelity, AssemblyRigidityMatchesTheClosedForm) {
  // Ring-sector fibers keep each sector's polar moment, so I_y = I_z = J / 2 exactly.
  const BraceSpec spec = test::girona_d3_restrained();
  EXPECT_NEAR(casing_assembly_flexural_rigidity(spec) / closed_form_rigidity(spec), 1.0, 1e-9);
}

TEST(AutoFidelity, AStiffSteelCasingWithLowFrictionRunsAsATruss) {
  const BraceSpec spec = test::girona_d3_restrained();
  const FidelityChoice choice = choose_auto_fidelity(spec);
  EXPECT_EQ(choice.fidelity, Fidelity::truss) << choice.reason;
  EXPECT_GT(choice.euler_ratio, kEulerMargin);
}

TEST(AutoFidelity, EveryConditionThatATrussMissesSelectsFull) {
  BraceSpec bare = test::girona_d3_restrained();
  bare.casing.reset();
  EXPECT_EQ(choose_auto_fidelity(bare).fidelity, Fidelity::full);

  BraceSpec weak = test::girona_d3_restrained(); // the global-buckling test's casing
  weak.casing->tube.diameter = 60.0;
  weak.casing->tube.wall = 2.0;
  const FidelityChoice weak_choice = choose_auto_fidelity(weak);
  EXPECT_EQ(weak_choice.fidelity, Fidelity::full);
  EXPECT_LT(weak_choice.euler_ratio, 1.0);

  BraceSpec rough = test::girona_d3_restrained();
  rough.casing->friction_coefficient = 0.3;
  EXPECT_EQ(choose_auto_fidelity(rough).fidelity, Fidelity::full);

  BraceSpec mortar_only = test::girona_d3_restrained();
  mortar_only.casing->steel_tube = false;
  EXPECT_EQ(choose_auto_fidelity(mortar_only).fidelity, Fidelity::full);
}

} // namespace
} // namespace brb::model
