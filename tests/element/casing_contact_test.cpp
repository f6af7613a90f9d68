// CasingContact: gap closure, mortar bearing with crushing, axial Coulomb friction.
#include "brb/element/casing_contact.hpp"

#include "support/finite_difference.hpp"

#include <gtest/gtest.h>

#include <cmath>

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

} // namespace
} // namespace brb::element
