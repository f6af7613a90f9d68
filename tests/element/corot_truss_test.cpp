// CorotTruss: large rotations, consistent tangent, and a snap-through truss.
#include "brb/element/corot_truss.hpp"
#include "brb/element/rotation.hpp"
#include "brb/material/steel_uniaxial.hpp"

#include "support/finite_difference.hpp"
#include "support/steel_fixtures.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace brb::element {
namespace {

using SteelTruss = CorotTruss<material::SteelUniaxial>;

TEST(CorotTruss, RigidRotationGivesNoForceAndStretchFollowsTheLaw) {
  // Reference: rigid motion does no work; a stretch along any direction gives
  // N = A sigma((l - L0) / L0) of the uniaxial law.
  const auto steel = test::linear_mixed_steel();
  const Vector3 a(0, 0, 0), b(1000, 0, 0);
  SteelTruss truss({0, 1}, a, b, 100.0, material::SteelUniaxial(steel, 1000.0));
  const Matrix3 q = rotation_from_vector(Vector3(0.3, -1.1, 0.7));
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;
  std::string failure;
  std::vector<NodeConfiguration> nodes{{q * a, q}, {q * b, q}};
  ASSERT_TRUE(truss.evaluate(nodes, force, tangent, failure));
  EXPECT_LT(force.norm(), 1e-10 * steel.youngs_modulus * 100.0); // relative to E A (round-off)
  nodes[1].position = q * Vector3(1003.0, 0, 0);                 // 0.3 % strain: yielded
  ASSERT_TRUE(truss.evaluate(nodes, force, tangent, failure));
  const material::SteelUniaxial law(steel, 1000.0);
  const double expected = 100.0 * law.evaluate(law.initial_state(), 0.003).stress;
  EXPECT_NEAR(force.segment<3>(6).norm(), expected, 1e-9 * expected);
}

TEST(CorotTruss, TangentMatchesFiniteDifferences) {
  // Reference: central differences of the nodal forces at a rotated, yielded configuration.
  SteelTruss truss({0, 1}, Vector3(0, 0, 0), Vector3(800, 300, -200), 50.0,
                   material::SteelUniaxial(test::chaboche_voce_steel(), 900.0));
  std::vector<NodeConfiguration> nodes{{Vector3(1, 2, 3), Matrix3::Identity()},
                                       {Vector3(700, 500, -150), Matrix3::Identity()}};
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;
  std::string failure;
  ASSERT_TRUE(truss.evaluate(nodes, force, tangent, failure));
  const auto force_of = [&](const Eigen::VectorXd& u) {
    auto moved = nodes;
    moved[0].position += u.segment<3>(0);
    moved[1].position += u.segment<3>(6);
    Eigen::VectorXd f;
    Eigen::MatrixXd unused;
    std::string why;
    EXPECT_TRUE(truss.evaluate(moved, f, unused, why));
    return f;
  };
  const Eigen::MatrixXd numeric =
      test::central_difference_jacobian(force_of, Eigen::VectorXd::Zero(12).eval(), 1e-6);
  EXPECT_LT(test::relative_difference(tangent, numeric), 1e-6);
}

} // namespace
} // namespace brb::element
