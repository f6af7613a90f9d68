// CasingSplitting: a mortar-only casing whose walls beside the core's opening crack in tension
// when the core presses its faces (issue 4/6, the thesis's small BRB).
#include "brb/element/casing_contact.hpp"

#include "support/expansion_probe.hpp"
#include "support/finite_difference.hpp"
#include "support/link_tangent.hpp"

#include <gtest/gtest.h>

#include "brb/material/parameter_error.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace brb::element {
namespace {

using test::ExpansionProbe;

constexpr double kMortarE = 17520.0;
constexpr double kTensileStrength = 3.992;

/// The small BRB's link (BRB_SOURCE_FACTS section 6: mortar E 17520, fc 39.92, ft 3.992 MPa,
/// Gf 0.75 N/mm): a 10 mm core station of 10 mm tributary length in a 30 x 30 mm outline, so
/// each face bears over 10 x 10 mm through 10 mm of mortar and the walls beside the opening
/// are 20 mm x 10 mm, stretched over 30 mm.
CasingContactParameters split_link(double gap) {
  CasingContactParameters parameters;
  parameters.gap_y = gap;
  parameters.gap_z = gap;
  parameters.bearing_area_y = 100.0;
  parameters.bearing_area_z = 100.0;
  parameters.bearing_depth_y = 10.0;
  parameters.bearing_depth_z = 10.0;
  parameters.mortar = {kMortarE, 0.2, 39.92, kTensileStrength, 0.75};
  parameters.layer_stiffness = 1e-3;
  parameters.friction_coefficient = 0.1;
  parameters.tangential_stiffness = 1e5;
  CasingSplitting splitting;
  splitting.wall_area_y = 200.0;
  splitting.wall_area_z = 200.0;
  splitting.wall_length_y = 30.0;
  splitting.wall_length_z = 30.0;
  parameters.splitting = splitting;
  return parameters;
}

// bearing stiffness of a face A E / depth and the walls' A_w E / L_w (N/mm)
constexpr double kFaceStiffness = 100.0 * kMortarE / 10.0;
constexpr double kWallStiffness = 200.0 * kMortarE / 30.0;

TEST(CasingSplitting, ParametersAreChecked) {
  auto parameters = split_link(0.05);
  parameters.splitting->wall_area_z = 0.0;
  EXPECT_THROW(parameters.validate(), brb::ParameterError);
  parameters = split_link(0.05);
  parameters.splitting->wall_length_y = -30.0;
  EXPECT_THROW(parameters.validate(), brb::ParameterError);
  EXPECT_NO_THROW(split_link(0.05).validate());
}

TEST(CasingSplitting, ABearingOnOneFaceStretchesTheWallsByHalfItsForce) {
  // Reference (theory, elastic): the face (k_f) in series with the split, whose walls (k_w)
  // carry the symmetric half of the face's force: k_w w = F / 2, F = k_f (p - w / 2), so
  // F = k_f p k_w / (k_w + k_f / 4). p = 0.004 mm keeps the walls below f_t (798 N).
  const auto parameters = split_link(0.05);
  CasingContact contact({0, 1}, Vector3::Zero(), Vector3::Zero(), parameters);
  std::vector<NodeConfiguration> nodes(2);
  const double penetration = 0.004;
  nodes[0].position = Vector3(0.0, 0.05 + penetration, 0.0);
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;
  std::string failure;
  ASSERT_TRUE(contact.evaluate(nodes, force, tangent, failure)) << failure;
  const double expected =
      kFaceStiffness * penetration * kWallStiffness / (kWallStiffness + 0.25 * kFaceStiffness);
  EXPECT_NEAR(contact.face_forces()[0], expected, 1e-9 * expected);
  EXPECT_NEAR(contact.split_force()[0], 0.5 * expected, 1e-9 * expected);
  EXPECT_NEAR(contact.split_opening()[0], 0.5 * expected / kWallStiffness, 1e-12);
  EXPECT_EQ(contact.split_opening()[1], 0.0); // the z faces are open
  EXPECT_EQ(contact.max_mortar_damage(), 0.0);
  // the lateral stiffness is the series one: k_f k_w / (k_w + k_f / 4)
  EXPECT_NEAR(tangent(1, 1) - parameters.layer_stiffness, expected / penetration,
              1e-9 * expected / penetration);
  // without the split the face bears k_f p
  auto rigid = parameters;
  rigid.splitting.reset();
  CasingContact rigid_contact({0, 1}, Vector3::Zero(), Vector3::Zero(), rigid);
  ASSERT_TRUE(rigid_contact.evaluate(nodes, force, tangent, failure)) << failure;
  EXPECT_NEAR(rigid_contact.face_forces()[0], kFaceStiffness * penetration, 1e-9);
}

TEST(CasingSplitting, AnExpandingCoreCracksTheWallsAtTheTensileStrengthLongBeforeCrushing) {
  // Reference (theory): a straight core at axial strain eps (no lateral motion, no gap)
  // grows by e = 0.5 |eps| 10 / 2 per side and presses both faces of each direction equally,
  // so the walls carry the whole face force, T = (F + F) / 2 = F: elastic,
  // F = k_f e k_w / (k_w + k_f / 2); the largest force is the walls' strength f_t A_w = 798.4
  // N (a face pressure of 8 MPa, a fifth of the crushing f_c = 39.92 MPa; brb solid on the
  // same brace cracks its mortar at about 9 MPa, validation/README.md), then it softens with
  // G_f and the faces stay uncrushed.
  const auto parameters = split_link(0.0);
  ExpansionProbe probe(parameters, 10.0, 10.0);
  double largest = 0.0;
  double largest_mismatch = 0.0;
  const int steps = 2000;
  for (int k = 1; k <= steps; ++k) {
    const double strain = -0.03 * k / steps;
    probe.place(Vector3::Zero(), strain);
    probe.evaluate();
    probe.contact.commit();
    const double face = probe.contact.face_forces()[0];
    EXPECT_EQ(face, probe.contact.face_forces()[1]);
    EXPECT_NEAR(face, probe.contact.face_forces()[2], 1e-9 * face);
    largest = std::max(largest, face);
    // T = (F+ + F-) / 2 at every step (the opening's equation, solved to rounding)
    largest_mismatch =
        std::max(largest_mismatch, std::abs(probe.contact.split_force()[0] - face) / face);
    if (k == 1) {
      const double e = 0.25 * 0.03 / steps * 10.0;
      const double elastic =
          kFaceStiffness * e * kWallStiffness / (kWallStiffness + 0.5 * kFaceStiffness);
      EXPECT_NEAR(face, elastic, 1e-9 * elastic);
    }
  }
  EXPECT_LT(largest_mismatch, 1e-10);
  const double strength = kTensileStrength * 200.0;
  EXPECT_NEAR(largest, strength, 2e-3 * strength);
  // at 3 % the walls are cracked through (damage > 0.9) and the bearing pressure is below
  // f_t A_w / A = 8 MPa: the faces never reached f_c
  const auto damage = probe.contact.split_damage();
  EXPECT_GT(damage[0], 0.9);
  EXPECT_GT(damage[1], 0.9);
  EXPECT_LT(probe.contact.face_forces()[0], strength);
  EXPECT_GT(probe.contact.face_forces()[0], 0.3 * strength); // G_f: a slow softening
  EXPECT_EQ(probe.contact.max_mortar_damage(), std::max(damage[0], damage[1]));
  // unloading: the cracked walls close with the faces (secant), the opening returns to 0
  probe.place(Vector3::Zero(), 0.001);
  probe.evaluate();
  EXPECT_EQ(probe.contact.split_opening()[0], 0.0);
  EXPECT_FALSE(probe.contact.in_contact());
}

TEST(CasingSplitting, TangentMatchesFiniteDifferencesWithCrackedWallsWhileSliding) {
  // Reference: central differences of the nodal forces of the four-node link; rotated axes,
  // the core expanded so that both y faces bear with a lateral offset (unequal faces), one z
  // face pressed by the lateral motion, the walls cracked in an earlier committed step,
  // friction sliding.
  auto parameters = split_link(0.02);
  parameters.axes = Eigen::AngleAxisd(0.4, Vector3(0.2, 0.5, 1.0).normalized()).toRotationMatrix();
  ExpansionProbe probe(parameters, 10.0, 10.0);
  probe.place(Vector3(0.1, 0.001, 0.03), -0.02);
  probe.evaluate();
  probe.contact.commit();
  probe.place(Vector3(0.4, 0.002, 0.05), -0.03);
  probe.evaluate();
  probe.contact.commit();
  EXPECT_GT(probe.contact.split_damage()[0], 0.5);
  probe.place(Vector3(0.7, 0.0025, 0.052), -0.0302, Vector3(0.0, 0.2, -0.1), Vector3::Zero());
  probe.evaluate();
  const auto& faces = probe.contact.face_forces();
  ASSERT_GT(faces[0], 0.0);
  ASSERT_GT(faces[1], 0.0);
  ASSERT_GT(faces[2], 0.0);
  ASSERT_NE(faces[0], faces[1]);
  EXPECT_NEAR(std::abs(probe.contact.link_force()[0]), 0.1 * probe.contact.normal_force(),
              1e-9 * probe.contact.normal_force());
  const Eigen::MatrixXd numeric = test::numeric_element_tangent(probe.contact, probe.nodes);
  EXPECT_LT(test::relative_difference(probe.tangent, numeric), 1e-6);
  EXPECT_LT(test::relative_difference(probe.tangent.rightCols(12), numeric.rightCols(12)), 1e-6);
}

TEST(CasingSplitting, TwoNodeLinkTangentMatchesFiniteDifferencesOnOneFace) {
  // Reference: central differences; the core pressed into +y past the walls' strength (the
  // split softening) and into -z, sliding.
  auto parameters = split_link(0.05);
  parameters.axes = Eigen::AngleAxisd(-0.3, Vector3(1.0, 0.3, 0.2).normalized()).toRotationMatrix();
  CasingContact contact({0, 1}, Vector3::Zero(), Vector3::Zero(), parameters);
  std::vector<NodeConfiguration> nodes(2);
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;
  std::string failure;
  nodes[0].position = parameters.axes * Vector3(0.2, 0.08, -0.06);
  ASSERT_TRUE(contact.evaluate(nodes, force, tangent, failure)) << failure;
  contact.commit();
  nodes[0].position = parameters.axes * Vector3(0.5, 0.085, -0.061);
  ASSERT_TRUE(contact.evaluate(nodes, force, tangent, failure)) << failure;
  EXPECT_GT(contact.split_damage()[0], 0.0);
  const Eigen::MatrixXd numeric = test::numeric_element_tangent(contact, nodes);
  EXPECT_LT(test::relative_difference(tangent, numeric), 1e-6);
}

TEST(CasingSplitting, WorkEqualsStoredPlusDissipatedAlongALoadingPath) {
  // Reference: energy conservation, as for the rigid casing (casing_contact_test.cpp): the
  // work of the nodal forces along a path in and out of contact on every face, with the
  // walls cracking, equals stored + dissipated (the walls' energy included).
  auto parameters = split_link(0.02);
  parameters.axes = Eigen::AngleAxisd(0.7, Vector3(1.0, 2.0, 0.5).normalized()).toRotationMatrix();
  ExpansionProbe probe(parameters, 10.0, 10.0);
  const ExpansionProbe::PathWalk walk = probe.walk_energy_path(40000, 0.08, 0.08);
  const double work = walk.work;
  const ElementEnergy energy = probe.contact.energy();
  const auto damage = probe.contact.split_damage();
  // both faces of a direction bear while the walls hold; once cracked, the casing opens
  // until the faces' mean force is the walls' small T, and a lateral offset lifts one face
  // (about 300 of the 40,000 points bear on both)
  EXPECT_GT(walk.both_faces, 100);
  EXPECT_GT(walk.open, 1000);
  EXPECT_GT(std::min(damage[0], damage[1]), 0.5);
  EXPECT_GT(energy.dissipated, 0.0);
  EXPECT_NEAR(work, energy.stored + energy.dissipated, 1e-4 * work);
  EXPECT_LT(walk.largest_mismatch, 1e-4 * work);
  // the link's own trapezoidal bookkeeping (its misfit) agrees with the nodal work
  EXPECT_LT(std::abs(energy.integration_misfit), 1e-4 * work);
}

} // namespace
} // namespace brb::element
