// CasingContact: gap closure, mortar bearing with crushing, axial Coulomb friction.
#include "brb/element/casing_contact.hpp"

#include "support/expansion_probe.hpp"
#include "support/finite_difference.hpp"
#include "support/link_tangent.hpp"

#include <gtest/gtest.h>

#include "brb/material/mortar_damage.hpp"
#include "brb/material/parameter_error.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace brb::element {
namespace {

/// The source's mortar (BRB_SOURCE_FACTS section 6, small BRB) bearing over 10 x 20 mm
/// faces, gap 0.12 mm (the source's contact pair), a soft layer. The bearing depth sets the
/// penetration at which the mortar crushes: fc / E x depth (0.023 mm for 10 mm).
CasingContactParameters small_brb_contact(double bearing_depth = 10.0) {
  CasingContactParameters parameters;
  parameters.gap_y = 0.12;
  parameters.gap_z = 0.12;
  parameters.bearing_area_y = 200.0;
  parameters.bearing_area_z = 200.0;
  parameters.bearing_depth_y = bearing_depth;
  parameters.bearing_depth_z = bearing_depth;
  parameters.mortar = {17520.0, 0.2, 39.92, 3.992, 0.75};
  parameters.layer_stiffness = 10.0;
  parameters.friction_coefficient = 0.1;
  parameters.tangential_stiffness = 1e5;
  return parameters;
}

struct Probe {
  CasingContact contact;
  std::vector<NodeConfiguration> nodes{{Vector3::Zero(), Matrix3::Identity()},
                                       {Vector3::Zero(), Matrix3::Identity()}};
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;

  explicit Probe(const CasingContactParameters& parameters)
      : contact({0, 1}, Vector3::Zero(), Vector3::Zero(), parameters) {}
  /// Moves the core node (casing fixed), evaluates and commits.
  void move_core(const Vector3& displacement) {
    nodes[0].position = displacement;
    std::string failure;
    ASSERT_TRUE(contact.evaluate(nodes, force, tangent, failure)) << failure;
    contact.commit();
  }
};

TEST(CasingContact, NoBearingUntilTheGapClosesThenMortarStiffness) {
  // Reference: the source's contact pair (BRB_SOURCE_FACTS section 6): no contact force
  // until the 0.12 mm gap closes; then the penalty law, here the elastic mortar bearing
  // A E / depth (below the crushing stress: depth 100 mm crushes at 0.23 mm) plus the layer
  // spring.
  const auto parameters = small_brb_contact(100.0);
  Probe probe(parameters);
  const double bearing_stiffness = parameters.bearing_area_y * 17520.0 / 100.0;
  for (int i = 1; i <= 25; ++i) {
    const double u = 0.01 * i; // ramp to 0.25 mm
    probe.move_core({0.0, u, 0.0});
    const double penetration = std::max(0.0, u - 0.12);
    const double expected = 10.0 * u + bearing_stiffness * penetration;
    EXPECT_NEAR(probe.force[1], expected, 1e-9 * (expected + 1.0)) << "u " << u;
    EXPECT_NEAR(probe.force[7], -expected, 1e-9 * (expected + 1.0));
    EXPECT_EQ(probe.contact.in_contact(), u > 0.12 + 1e-12);
  }
}

TEST(CasingContact, EachDirectionBearsOverItsOwnMortarDepth) {
  // Reference (theory): a plate core in a square tube has more mortar beside its thin side
  // than beside its wide side. Elastic bearing stiffness A E / depth per direction, and the
  // crushing penetration fc / E x depth, differ by the ratio of the depths (here 10 and
  // 40 mm, depth 100 mm would not crush in this range).
  auto parameters = small_brb_contact();
  parameters.bearing_depth_y = 10.0;
  parameters.bearing_depth_z = 40.0;
  const double penetration = 0.01; // elastic on both: crushing starts at 0.0228 mm for 10 mm
  Probe along_y(parameters);
  along_y.move_core({0.0, 0.12 + penetration, 0.0});
  Probe along_z(parameters);
  along_z.move_core({0.0, 0.0, 0.12 + penetration});
  const double layer = 10.0 * (0.12 + penetration);
  EXPECT_NEAR(along_y.force[1] - layer, 200.0 * 17520.0 / 10.0 * penetration, 1e-9);
  EXPECT_NEAR(along_z.force[2] - layer, 200.0 * 17520.0 / 40.0 * penetration, 1e-9);
  // Crushing: the y faces crush at 4x less penetration than the z faces.
  const double crush_y = 39.92 / 17520.0 * 10.0, crush_z = 39.92 / 17520.0 * 40.0;
  Probe crushing_y(parameters);
  crushing_y.move_core({0.0, 0.12 + 1.5 * crush_y, 0.0});
  EXPECT_GT(crushing_y.contact.max_mortar_damage(), 0.0);
  Probe holding_z(parameters);
  holding_z.move_core({0.0, 0.0, 0.12 + 1.5 * crush_y});
  EXPECT_EQ(holding_z.contact.max_mortar_damage(), 0.0);
  Probe crushing_z(parameters);
  crushing_z.move_core({0.0, 0.0, 0.12 + 1.5 * crush_z});
  EXPECT_GT(crushing_z.contact.max_mortar_damage(), 0.0);
}

TEST(CasingContact, BearingCrushesAtTheMortarStrengthOnThatFaceOnly) {
  // Reference: the mortar law in compression: damage starts at fc, so the bearing force
  // peaks at fc A and then softens; the opposite face keeps its full capacity.
  const auto parameters = small_brb_contact();
  Probe probe(parameters);
  double peak = 0.0;
  for (int i = 1; i <= 400; ++i) {
    const double crush_penetration = 39.92 / 17520.0 * parameters.bearing_depth_y;
    const double u = 0.12 + 5.0 * crush_penetration * i / 400.0; // to 5x the crush penetration
    probe.move_core({0.0, u, 0.0});
    peak = std::max(peak, probe.contact.link_force()[1] - 10.0 * u);
  }
  EXPECT_NEAR(peak, 39.92 * parameters.bearing_area_y, 0.01 * 39.92 * parameters.bearing_area_y);
  const double softened = probe.contact.link_force()[1] - 10.0 * probe.nodes[0].position.y();
  EXPECT_LT(softened, 0.99 * peak); // softening branch (slow: A is small for this Gf/lc)
  EXPECT_GT(probe.contact.max_mortar_damage(), 0.5);
  // the opposite face: elastic bearing from its own gap
  probe.move_core({0.0, -0.13, 0.0});
  const double opposite = -(probe.contact.link_force()[1] + 10.0 * 0.13);
  EXPECT_NEAR(opposite, parameters.bearing_area_y * 17520.0 / 10.0 * 0.01, 1e-6);
}

TEST(CasingContact, ACrushReachedWithoutAPathPointNearThePeakIsAJumpPastIt) {
  // Path control (Element::jumped_past_peak): depth 10 mm crushes at fc / E x depth =
  // 0.023 mm of penetration and the damage grows continuously from 0 there (MortarUniaxial).
  // A face intact at the last path point and crushed now jumped past its peak; a path that
  // visits a point near the peak did not.
  const auto parameters = small_brb_contact();
  const double crushing_penetration = 39.92 / 17520.0 * 10.0;
  const double gap = parameters.gap_y;
  std::string failure;
  {
    Probe probe(parameters);
    probe.contact.mark_path_point(); // the unloaded, intact link
    probe.nodes[0].position = {0.0, gap + 10.0 * crushing_penetration, 0.0};
    ASSERT_TRUE(probe.contact.evaluate(probe.nodes, probe.force, probe.tangent, failure));
    ASSERT_GT(probe.contact.max_mortar_damage(), CasingContact::kPathCrushedDamage);
    EXPECT_TRUE(probe.contact.jumped_past_peak());
    // a penetration short of the peak from the same path point: no jump
    probe.nodes[0].position = {0.0, gap + 0.5 * crushing_penetration, 0.0};
    ASSERT_TRUE(probe.contact.evaluate(probe.nodes, probe.force, probe.tangent, failure));
    EXPECT_FALSE(probe.contact.jumped_past_peak());
  }
  {
    // the same crush followed in small steps, each a path point: the state just past the
    // peak is on the path, so the crush that follows it is not a jump
    Probe probe(parameters);
    for (int i = 1; i <= 40; ++i) {
      probe.contact.mark_path_point();
      probe.move_core({0.0, gap + 0.05 * i * 2.0 * crushing_penetration, 0.0});
      EXPECT_FALSE(probe.contact.jumped_past_peak()) << "step " << i;
    }
    EXPECT_GT(probe.contact.max_mortar_damage(), CasingContact::kPathCrushedDamage);
  }
}

TEST(CasingContact, AxialFrictionIsBoundedByCoulomb) {
  // Reference: Coulomb's law, |T| <= kappa N, with equality while sliding.
  const auto parameters = small_brb_contact(100.0);
  Probe probe(parameters);
  probe.move_core({0.0, 0.15, 0.0}); // bearing N = A E/depth 0.03
  const double normal = parameters.bearing_area_y * 17520.0 / 100.0 * 0.03;
  probe.move_core({1e-6, 0.15, 0.0});
  EXPECT_NEAR(probe.contact.link_force()[0], 1e5 * 1e-6, 1e-9); // stick: k_T u
  probe.move_core({0.5, 0.15, 0.0});
  EXPECT_NEAR(probe.contact.link_force()[0], 0.1 * normal, 1e-9 * normal); // slip
  EXPECT_GT(probe.contact.energy().dissipated, 0.0);
}

TEST(CasingContact, TangentMatchesFiniteDifferences) {
  // Reference: central differences of the nodal forces, in contact and sliding, with
  // rotated brace axes (the link frame) and a committed crushed face.
  auto parameters = small_brb_contact();
  parameters.axes = Eigen::AngleAxisd(0.4, Vector3(0.2, 0.5, 1.0).normalized()).toRotationMatrix();
  Probe probe(parameters);
  probe.move_core(parameters.axes * Vector3(0.2, 0.13, -0.125));
  probe.move_core(parameters.axes * Vector3(0.4, 0.14, -0.127));
  const Vector3 at = parameters.axes * Vector3(0.6, 0.141, -0.1275);
  probe.nodes[0].position = at;
  std::string failure;
  ASSERT_TRUE(probe.contact.evaluate(probe.nodes, probe.force, probe.tangent, failure));
  const auto force_of = [&](const Eigen::VectorXd& u) {
    auto moved = probe.nodes;
    moved[0].position += u.segment<3>(0);
    moved[1].position += u.segment<3>(6);
    Eigen::VectorXd f;
    Eigen::MatrixXd unused;
    std::string why;
    EXPECT_TRUE(probe.contact.evaluate(moved, f, unused, why));
    return f;
  };
  const Eigen::MatrixXd numeric =
      test::central_difference_jacobian(force_of, Eigen::VectorXd::Zero(12).eval(), 1e-8);
  EXPECT_LT(test::relative_difference(probe.tangent, numeric), 1e-6);
}

// --- the core's lateral (Poisson) expansion (issue 4) ---

using test::ExpansionProbe;

TEST(CasingContactExpansion, LinkHoldsTheChordNodesOnce) {
  // Interior station: core, casing and both neighbours; an end station: the station's own
  // core node is one end of the chord and is not listed twice.
  const auto parameters = small_brb_contact();
  ExpansionProbe interior(parameters, 10.0, 20.0);
  EXPECT_EQ(std::vector<int>(interior.contact.nodes().begin(), interior.contact.nodes().end()),
            (std::vector<int>{0, 1, 2, 3}));
  CoreExpansion end = ExpansionProbe::expansion(parameters.axes, 10.0, 20.0);
  end.previous_node = 0;
  end.previous_position = Vector3::Zero();
  CasingContact end_link({0, 1}, Vector3::Zero(), Vector3::Zero(), parameters, true, end);
  EXPECT_EQ(std::vector<int>(end_link.nodes().begin(), end_link.nodes().end()),
            (std::vector<int>{0, 1, 3}));
  CoreExpansion wrong = end;
  wrong.ratio = 0.6;
  EXPECT_THROW(CasingContact({0, 1}, Vector3::Zero(), Vector3::Zero(), parameters, true, wrong),
               brb::ParameterError);
}

Eigen::MatrixXd numeric_tangent(CasingContact& contact,
                                const std::vector<NodeConfiguration>& configuration) {
  return test::numeric_element_tangent(contact, configuration);
}

TEST(CasingContactExpansion, TangentMatchesFiniteDifferencesOnBothFacesWhileSliding) {
  // Reference: central differences of the nodal forces of the four-node link (core, casing,
  // both chord nodes), rotated axes, the core compressed by 5 % so that both y faces bear
  // (e_y = 0.5 x 0.05 x 10 / 2 = 0.125 mm against a 0.12 mm gap plus a small lateral
  // motion) and one z face (lateral motion), with a crushed +z face committed, friction
  // sliding, and a bowed chord (its direction off the axis: the chord's curvature term).
  auto parameters = small_brb_contact(100.0);
  parameters.axes = Eigen::AngleAxisd(0.4, Vector3(0.2, 0.5, 1.0).normalized()).toRotationMatrix();
  ExpansionProbe probe(parameters, 10.0, 20.0);
  const Vector3 bow(0.0, 0.3, -0.2);
  probe.place(Vector3(0.2, 0.002, 0.1), -0.03, bow, -bow);
  probe.evaluate();
  probe.contact.commit();
  probe.place(Vector3(0.6, 0.003, 0.4), -0.05, bow, -0.5 * bow);
  probe.evaluate();
  probe.contact.commit();
  EXPECT_GT(probe.contact.max_mortar_damage(), 0.0); // +z crushed (0.4 - 0.12 + 0.25 mm)
  probe.place(Vector3(0.9, 0.0035, 0.41), -0.0502, bow, -0.5 * bow);
  probe.evaluate();
  const auto& faces = probe.contact.face_forces();
  ASSERT_GT(faces[0], 0.0);
  ASSERT_GT(faces[1], 0.0);
  ASSERT_GT(faces[2], 0.0);
  EXPECT_EQ(faces[3], 0.0);
  // sliding: |T| = kappa N, N the sum of the faces
  EXPECT_NEAR(probe.contact.normal_force(), faces[0] + faces[1] + faces[2] + faces[3], 1e-9);
  EXPECT_NEAR(std::abs(probe.contact.link_force()[0]), 0.1 * probe.contact.normal_force(),
              1e-9 * probe.contact.normal_force());
  ASSERT_EQ(probe.tangent.rows(), 24);
  const Eigen::MatrixXd numeric = numeric_tangent(probe.contact, probe.nodes);
  EXPECT_LT(test::relative_difference(probe.tangent, numeric), 1e-6);
  // the chord's columns on their own (their entries, k m / l0, are small next to the
  // bearing stiffness k, so the whole matrix's norm would hide an error in them)
  EXPECT_GT(numeric.rightCols(12).norm(), 0.0);
  EXPECT_LT(test::relative_difference(probe.tangent.rightCols(12), numeric.rightCols(12)), 1e-6);
  EXPECT_LT(test::relative_difference(probe.tangent.bottomRows(12), numeric.bottomRows(12)), 1e-6);
}

TEST(CasingContactExpansion, EndStationTangentMatchesFiniteDifferences) {
  // Reference: central differences; an end station whose chord runs from its own core node
  // to the next one (three nodes), the core pressed on both z faces and sliding.
  auto parameters = small_brb_contact(100.0);
  parameters.axes = Eigen::AngleAxisd(-0.3, Vector3(1.0, 0.3, 0.2).normalized()).toRotationMatrix();
  CoreExpansion end = ExpansionProbe::expansion(parameters.axes, 10.0, 20.0);
  end.previous_node = 0;
  end.previous_position = Vector3::Zero();
  CasingContact contact({0, 1}, Vector3::Zero(), Vector3::Zero(), parameters, true, end);
  std::vector<NodeConfiguration> nodes(3);
  const auto place = [&](const Vector3& core, const Vector3& next) {
    nodes[0].position = parameters.axes * core;
    nodes[2].position = parameters.axes * next;
  };
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;
  std::string failure;
  place(Vector3(0.1, 0.0, 0.01), Vector3(47.0, 0.05, 0.02)); // eps -0.06: e_z 0.3 mm
  ASSERT_TRUE(contact.evaluate(nodes, force, tangent, failure));
  contact.commit();
  place(Vector3(0.5, 0.001, 0.015), Vector3(47.1, 0.06, 0.03));
  ASSERT_TRUE(contact.evaluate(nodes, force, tangent, failure));
  ASSERT_GT(contact.face_forces()[2], 0.0);
  ASSERT_GT(contact.face_forces()[3], 0.0);
  ASSERT_EQ(tangent.rows(), 18);
  const Eigen::MatrixXd numeric = numeric_tangent(contact, nodes);
  EXPECT_LT(test::relative_difference(tangent, numeric), 1e-6);
}

TEST(CasingContactExpansion, UniformlyCompressedStraightCoreBearsOnBothFacesOnceTheGapCloses) {
  // Reference (theory): a straight core at uniform axial strain eps with no lateral motion
  // grows by e = 0.5 |eps| h / 2 per side. No bearing while e < gap; past it each face of
  // that direction bears with A sigma((e - gap) / depth), here elastic (depth 100 mm: the
  // mortar crushes at 0.228 mm, more than the largest e - gap = 0.1 mm), A E (e - gap) /
  // depth; equal and opposite forces (no net lateral force), friction's normal force their
  // sum, and on the chord's ends the energy's derivative: dW/deps / l0 along the chord, with
  // dW/deps = -(h_y / 4) (S_+y + S_-y) - (h_z / 4) (S_+z + S_-z).
  auto parameters = small_brb_contact(100.0);
  parameters.gap_y = 0.1; // y faces close at |eps| = 4 gap / h_y = 0.04
  parameters.gap_z = 0.3; // z faces at 4 x 0.3 / 20 = 0.06
  parameters.bearing_area_z = 300.0;
  ExpansionProbe probe(parameters, 10.0, 20.0);
  int y_bearing = 0, z_bearing = 0;
  for (int i = 0; i <= 80; ++i) {
    const double strain = -0.001 * i;
    probe.place(Vector3::Zero(), strain);
    probe.evaluate();
    probe.contact.commit();
    const double closure_y = 0.5 * std::abs(strain) * 10.0 / 2.0 - 0.1;
    const double closure_z = 0.5 * std::abs(strain) * 20.0 / 2.0 - 0.3;
    const double face_y = closure_y > 0.0 ? 200.0 * 17520.0 * closure_y / 100.0 : 0.0;
    const double face_z = closure_z > 0.0 ? 300.0 * 17520.0 * closure_z / 100.0 : 0.0;
    const auto& faces = probe.contact.face_forces();
    const double scale = 1e-9 * (face_y + face_z + 1.0);
    EXPECT_NEAR(faces[0], face_y, scale) << "eps " << strain;
    EXPECT_NEAR(faces[1], face_y, scale) << "eps " << strain;
    EXPECT_NEAR(faces[2], face_z, scale) << "eps " << strain;
    EXPECT_NEAR(faces[3], face_z, scale) << "eps " << strain;
    EXPECT_NEAR(probe.contact.normal_force(), 2.0 * (face_y + face_z), 4.0 * scale);
    EXPECT_EQ(probe.contact.in_contact(), face_y + face_z > 0.0);
    // no net lateral force on core or casing, and no friction without axial sliding
    EXPECT_NEAR(probe.force.segment<3>(0).norm(), 0.0, scale);
    EXPECT_NEAR(probe.force.segment<3>(6).norm(), 0.0, scale);
    const double energy_rate = -(10.0 / 4.0) * 2.0 * face_y - (20.0 / 4.0) * 2.0 * face_z;
    const Vector3 on_next =
        energy_rate / (2.0 * ExpansionProbe::half_chord) * parameters.axes.col(0);
    EXPECT_NEAR((probe.force.segment<3>(18) - on_next).norm(), 0.0, scale);
    EXPECT_NEAR((probe.force.segment<3>(12) + on_next).norm(), 0.0, scale);
    y_bearing += face_y > 0.0;
    z_bearing += face_z > 0.0;
  }
  EXPECT_GT(y_bearing, 30); // both regimes visited
  EXPECT_GT(z_bearing, 10);
  // Sliding the core along the casing: Coulomb on the sum of the four faces.
  probe.place(Vector3(0.5, 0.0, 0.0), -0.08);
  probe.evaluate();
  EXPECT_NEAR(std::abs(probe.contact.link_force()[0]), 0.1 * probe.contact.normal_force(),
              1e-9 * probe.contact.normal_force());
  // Tension shrinks the core: the gaps stay open.
  probe.place(Vector3::Zero(), 0.05);
  probe.evaluate();
  EXPECT_EQ(probe.contact.normal_force(), 0.0);
  EXPECT_LT(probe.contact.core_expansion()[0], 0.0);
}

TEST(CasingContactExpansion, CrushingFollowsTheMortarLawAtTheExpansionPenetration) {
  // Reference: the mortar law itself (material::MortarUniaxial, tested on its own), driven
  // independently at the strain -(0.5 |eps| h / 2 - gap) / depth of a face: the link's face
  // force is A times its stress through crushing and softening.
  const auto parameters = small_brb_contact(10.0); // crushes at 0.0228 mm
  ExpansionProbe probe(parameters, 10.0, 10.0);
  const material::MortarUniaxial law(parameters.mortar, 10.0);
  material::MortarState state;
  for (int i = 0; i <= 120; ++i) {
    const double strain = -0.0006 * i; // e up to 0.18 mm, 0.06 mm past the gap
    probe.place(Vector3::Zero(), strain);
    probe.evaluate();
    probe.contact.commit();
    const double closure = 0.5 * std::abs(strain) * 10.0 / 2.0 - 0.12;
    double expected = 0.0;
    if (closure > 0.0) {
      const auto response = law.evaluate(state, -closure / 10.0);
      state = response.state;
      expected = -200.0 * response.stress;
    }
    for (const double face : probe.contact.face_forces())
      EXPECT_NEAR(face, expected, 1e-9 * (expected + 1.0)) << "eps " << strain;
  }
  EXPECT_GT(state.damage, 0.5); // the test went through crushing
  EXPECT_NEAR(probe.contact.max_mortar_damage(), state.damage, 1e-12);
}

TEST(CasingContactExpansion, WorkEqualsStoredPlusDissipatedAlongALoadingPath) {
  // Reference: energy conservation. Along a path of lateral motion, axial sliding and axial
  // strain of the chord, in and out of contact on every face (crushing, friction slip), the
  // work of the nodal forces (trapezoidal rule over small steps) equals the change of
  // stored + dissipated energy.
  auto parameters = small_brb_contact(10.0);
  parameters.axes = Eigen::AngleAxisd(0.7, Vector3(1.0, 2.0, 0.5).normalized()).toRotationMatrix();
  ExpansionProbe probe(parameters, 10.0, 20.0);
  const ExpansionProbe::PathWalk walk = probe.walk_energy_path(40000, 0.2, 0.06);
  const double work = walk.work;
  const ElementEnergy energy = probe.contact.energy();
  EXPECT_GT(walk.both_faces, 1000);
  EXPECT_GT(walk.open, 1000);
  EXPECT_GT(walk.max_damage, 0.5);
  EXPECT_GT(energy.dissipated, 0.0);
  EXPECT_NEAR(work, energy.stored + energy.dissipated, 1e-4 * work);
  EXPECT_LT(walk.largest_mismatch, 1e-4 * work); // at every point of the path, stored > 0 or not
}

TEST(CasingContact, StressWorkIsTheNodalForcesTrapezoidalWorkAndItsMisfitTheGapClosing) {
  // Reference (by hand): a face closing inside a step. From rest the core moves 0.2 mm
  // along y in one step: the face penetrates p = 0.2 - 0.12 = 0.08 mm with the elastic
  // bearing force F = A E p / depth (depth 100 mm: no crushing). The trapezoidal rule sums
  // F / 2 over the whole 0.2 mm, the law stores F p / 2: the misfit is F / 2 x 0.12 mm (the
  // layer spring is linear and adds none).
  const auto parameters = small_brb_contact(100.0);
  Probe probe(parameters);
  probe.move_core({0.0, 0.2, 0.0});
  const double bearing_force = parameters.bearing_area_y * 17520.0 / 100.0 * 0.08;
  EXPECT_NEAR(probe.contact.face_forces()[0], bearing_force, 1e-9 * bearing_force);
  EXPECT_NEAR(probe.contact.energy().integration_misfit, 0.5 * bearing_force * 0.12,
              1e-9 * bearing_force);

  // Reference: along a coarse path (rotated axes; faces opening and closing, crushing,
  // friction slip, in 400 steps) the trapezoidal work of the nodal forces equals stored +
  // dissipated + integration misfit to round-off (the link's kinematics are linear), while
  // the laws' own balance misses by the misfit, which is not small at this step.
  auto rotated = small_brb_contact(10.0);
  rotated.axes = Eigen::AngleAxisd(0.7, Vector3(1.0, 2.0, 0.5).normalized()).toRotationMatrix();
  Probe path(rotated);
  const int steps = 400;
  double work = 0.0;
  Eigen::VectorXd previous_force = Eigen::VectorXd::Zero(12);
  Vector3 previous_core = Vector3::Zero();
  double largest_mismatch = 0.0;
  for (int k = 1; k <= steps; ++k) {
    const double t = 2.0 * std::numbers::pi * k / steps;
    const Vector3 local(0.1 * std::sin(t), 0.5 * std::sin(2.0 * t), 0.2 * std::sin(3.0 * t));
    const Vector3 core = rotated.axes * local;
    path.move_core(core);
    work +=
        0.5 * (previous_force.segment<3>(0) + path.force.segment<3>(0)).dot(core - previous_core);
    previous_force = path.force;
    previous_core = core;
    const ElementEnergy now = path.contact.energy();
    largest_mismatch = std::max(
        largest_mismatch, std::abs(work - now.stored - now.dissipated - now.integration_misfit));
  }
  const ElementEnergy energy = path.contact.energy();
  EXPECT_GT(path.contact.max_mortar_damage(), 0.5);
  EXPECT_LT(largest_mismatch, 1e-11 * work);
  EXPECT_GT(std::abs(energy.integration_misfit), 1e-4 * work);
}

} // namespace
} // namespace brb::element
