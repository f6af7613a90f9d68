// The exact work skips (DESIGN.md section 10, model/work_skips.hpp) change nothing: switched
// on or off, the law, the link and a whole cyclic test of the restrained Girona D3 brace give
// the same numbers bit for bit. Reference: the same code with the skip off (the general path),
// so any difference, down to the last bit, is an error of the skip. Bitwise and not 1e-12:
// each skip returns the very products the general path computes (the skipped terms add
// exactly zero), so nothing may differ.
#include "brb/analysis/cyclic_test.hpp"
#include "brb/element/casing_contact.hpp"
#include "brb/io/protocol.hpp"
#include "brb/material/steel_uniaxial.hpp"
#include "brb/model/brace_model.hpp"
#include "brb/model/work_skips.hpp"

#include "support/brace_fixtures.hpp"
#include "support/steel_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <random>
#include <vector>

namespace {

using namespace brb;

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}

void expect_same_state(const material::SteelStateUniaxial& a,
                       const material::SteelStateUniaxial& b) {
  EXPECT_TRUE(same_bits(a.plastic_strain, b.plastic_strain));
  EXPECT_TRUE(same_bits(a.equivalent_plastic_strain, b.equivalent_plastic_strain));
  EXPECT_TRUE(same_bits(a.damage_threshold, b.damage_threshold));
  EXPECT_TRUE(same_bits(a.damage, b.damage));
  EXPECT_TRUE(same_bits(a.dissipated.total, b.dissipated.total));
  EXPECT_TRUE(same_bits(a.dissipated.plastic, b.dissipated.plastic));
  EXPECT_TRUE(same_bits(a.dissipated.softening, b.dissipated.softening));
  for (int k = 0; k < material::HardeningTerms::kMax; ++k)
    EXPECT_TRUE(same_bits(a.back_stress[k], b.back_stress[k]));
}

TEST(WorkSkips, DefaultsAreAllOnAndNoneIsAllOff) {
  const model::WorkSkips on;
  EXPECT_TRUE(on.open_links && on.elastic_fast_path && on.reuse_tangents &&
              on.requested_recorders && on.auto_fidelity);
  const model::WorkSkips off = model::WorkSkips::none();
  EXPECT_FALSE(off.open_links || off.elastic_fast_path || off.reuse_tangents ||
               off.requested_recorders || off.auto_fidelity);
}

// Random cyclic strains through elastic unloading, yielding and damage growth (damaging steel,
// fu 430 MPa): every response and state of the fast path equals the general path's.
TEST(WorkSkips, SteelElasticFastPathIsBitwiseTheGeneralPath) {
  material::SteelUniaxial fast(test::damaging_steel(), 50.0);
  material::SteelUniaxial general(test::damaging_steel(), 50.0);
  general.set_elastic_fast_path(false);
  ASSERT_TRUE(fast.elastic_fast_path());
  ASSERT_FALSE(general.elastic_fast_path());
  std::mt19937 random(20261122);
  std::uniform_real_distribution<double> increment(-0.0015, 0.0017); // drifts into damage
  material::SteelStateUniaxial state_fast, state_general;
  double strain = 0.0;
  int elastic_points = 0, damaged_points = 0;
  for (int step = 0; step < 4000; ++step) {
    strain += increment(random);
    const auto a = fast.evaluate(state_fast, strain);
    const auto b = general.evaluate(state_general, strain);
    ASSERT_TRUE(same_bits(a.stress, b.stress)) << "step " << step;
    ASSERT_TRUE(same_bits(a.tangent, b.tangent)) << "step " << step;
    expect_same_state(a.state, b.state);
    elastic_points += a.state.equivalent_plastic_strain == state_fast.equivalent_plastic_strain;
    damaged_points += a.state.damage > 0.0;
    // a re-evaluation at the converged strain (what Newton does) is elastic: same again
    const auto again_fast = fast.evaluate(a.state, strain);
    const auto again_general = general.evaluate(b.state, strain);
    ASSERT_TRUE(same_bits(again_fast.stress, again_general.stress));
    ASSERT_TRUE(same_bits(again_fast.tangent, again_general.tangent));
    state_fast = a.state;
    state_general = b.state;
    if (a.state.damage > 0.99)
      break;
  }
  // the history visited both branches (otherwise the test shows nothing)
  EXPECT_GT(elastic_points, 100);
  EXPECT_GT(damaged_points, 10);
}

element::CasingContactParameters link_parameters() {
  element::CasingContactParameters link;
  link.gap_y = 0.5;
  link.gap_z = 0.8;
  link.bearing_area_y = 2000.0;
  link.bearing_area_z = 1500.0;
  link.bearing_depth_y = 40.0;
  link.bearing_depth_z = 30.0;
  link.mortar = {17520.0, 0.2, 50.0, 5.0, 0.1};
  link.layer_stiffness = 3.0;
  link.friction_coefficient = 0.1;
  link.tangential_stiffness = 1e6;
  // a rotated brace: the axes are not the global ones
  link.axes =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, 0.5).normalized()).toRotationMatrix();
  return link;
}

/// Random walks of the core relative to the casing (and, with an expansion, of the core's
/// axial strain at the station), in and out of contact, committed after each point: forces,
/// tangents and energies agree bit for bit with and without the open-link path. Returns the
/// number of points in contact.
int expect_open_links_bitwise(const std::optional<element::CoreExpansion>& expansion) {
  const element::CasingContactParameters link = link_parameters();
  const element::Vector3 position(100.0, 20.0, -5.0);
  element::CasingContact skipping({0, 1}, position, position, link, true, expansion);
  element::CasingContact general({0, 1}, position, position, link, false, expansion);
  const std::size_t node_count = expansion ? 4 : 2;
  const auto dofs = static_cast<Eigen::Index>(6 * node_count);
  std::mt19937 random(7);
  std::normal_distribution<double> step(0.0, 0.25);
  std::normal_distribution<double> strain_step(0.0, 0.01);
  element::Vector3 relative = element::Vector3::Zero();
  double strain = 0.0;
  std::vector<element::NodeConfiguration> nodes(node_count);
  nodes[1].position = position;
  Eigen::VectorXd force_a, force_b;
  Eigen::MatrixXd tangent_a, tangent_b;
  std::string failure;
  int contact_points = 0;
  for (int point = 0; point < 3000; ++point) {
    relative += element::Vector3(step(random), step(random), step(random));
    relative = relative.cwiseMax(-1.2).cwiseMin(1.2); // stay within a bearing depth
    nodes[0].position = position + link.axes * relative;
    if (expansion) {
      strain = std::clamp(strain + strain_step(random), -0.08, 0.03);
      const element::Vector3 half_chord =
          0.5 * (expansion->next_position - expansion->previous_position);
      nodes[2].position = position - (1.0 + strain) * half_chord;
      nodes[3].position = position + (1.0 + strain) * half_chord;
    }
    EXPECT_TRUE(skipping.evaluate(nodes, force_a, tangent_a, failure));
    EXPECT_TRUE(general.evaluate(nodes, force_b, tangent_b, failure));
    EXPECT_EQ(force_a.size(), dofs);
    EXPECT_EQ(tangent_a.rows(), dofs);
    EXPECT_EQ(tangent_b.rows(), dofs);
    if (force_a.size() != dofs || tangent_a.rows() != dofs || tangent_b.rows() != dofs)
      return contact_points;
    for (Eigen::Index i = 0; i < dofs; ++i) {
      EXPECT_TRUE(same_bits(force_a[i], force_b[i])) << "point " << point;
      for (Eigen::Index j = 0; j < dofs; ++j)
        EXPECT_TRUE(same_bits(tangent_a(i, j), tangent_b(i, j))) << "point " << point;
    }
    EXPECT_TRUE(same_bits(skipping.energy().stored, general.energy().stored));
    EXPECT_TRUE(same_bits(skipping.energy().dissipated, general.energy().dissipated));
    EXPECT_TRUE(
        same_bits(skipping.energy().integration_misfit, general.energy().integration_misfit));
    if (::testing::Test::HasFailure())
      return contact_points;
    contact_points += general.in_contact();
    skipping.commit();
    general.commit();
  }
  EXPECT_GT(skipping.open_evaluations(), 100);
  EXPECT_EQ(general.open_evaluations(), 0);
  return contact_points;
}

TEST(WorkSkips, OpenCasingLinkIsBitwiseTheGeneralPath) {
  EXPECT_GT(expect_open_links_bitwise(std::nullopt), 100);
}

// The four-node link with the core's expansion: the open test includes the expansion and the
// constant tangent has the link's 24 DOF; the walk of the core's strain (-8 % to 3 %, the
// expansion up to 0.8 mm against the 0.5 and 0.8 mm gaps) opens and closes faces by itself.
TEST(WorkSkips, OpenCasingLinkWithCoreExpansionIsBitwiseTheGeneralPath) {
  const element::CasingContactParameters link = link_parameters();
  const element::Vector3 position(100.0, 20.0, -5.0);
  element::CoreExpansion expansion;
  expansion.previous_node = 2;
  expansion.next_node = 3;
  expansion.previous_position = position - 60.0 * link.axes.col(0);
  expansion.next_position = position + 60.0 * link.axes.col(0);
  expansion.extent_y = 40.0;
  expansion.extent_z = 60.0;
  EXPECT_GT(expect_open_links_bitwise(expansion), 100);
}

struct CyclicRun {
  std::vector<double> force;
  double dissipated = 0.0;
  long open_evaluations = 0;
};

CyclicRun cyclic_run(const model::WorkSkips& skips) {
  const model::BraceSpec spec = test::girona_d3_restrained(4);
  model::BraceModel brace = model::build_brace_model(spec, skips);
  const double dy = brace.yield_deformation;
  const io::LoadingProtocol protocol =
      io::cyclic_protocol("short", {{0.5 * dy, 1}, {2.0 * dy, 1}}, 0.25 * dy);
  const analysis::CyclicTestResult result = analysis::run_cyclic_test(
      brace, protocol.deformation, protocol.cycle, protocol.cycle_amplitude);
  EXPECT_TRUE(result.completed) << result.stop_reason;
  CyclicRun run;
  for (const analysis::CyclicStep& step : result.steps)
    run.force.push_back(step.force);
  run.dissipated = result.energy_balance.dissipated;
  for (const element::CasingContact* contact : brace.casing->contacts)
    run.open_evaluations += contact->open_evaluations();
  return run;
}

// The full restrained D3 brace (4 core elements) through one cycle at 0.5 dy and one at 2 dy:
// switching off open links, the elastic fast path, or both, changes no force of the
// hysteresis by a single bit.
TEST(WorkSkips, ExactSkipsLeaveTheRestrainedBraceCyclicTestUnchanged) {
  const CyclicRun all_on = cyclic_run({});
  ASSERT_GT(all_on.force.size(), 20u);
  EXPECT_GT(all_on.open_evaluations, 0); // the skip had work to do
  model::WorkSkips open_off, fast_off;
  open_off.open_links = false;
  fast_off.elastic_fast_path = false;
  for (const model::WorkSkips& skips : {open_off, fast_off, model::WorkSkips::none()}) {
    const CyclicRun run = cyclic_run(skips);
    ASSERT_EQ(run.force.size(), all_on.force.size());
    for (std::size_t k = 0; k < run.force.size(); ++k)
      ASSERT_TRUE(same_bits(run.force[k], all_on.force[k])) << "step " << k;
    EXPECT_TRUE(same_bits(run.dissipated, all_on.dissipated));
    if (!skips.open_links) {
      EXPECT_EQ(run.open_evaluations, 0);
    }
  }
}

} // namespace
