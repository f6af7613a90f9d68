// ZeroLengthSpring: linear springs per global DOF between two nodes (the casing stopper).
#include "brb/element/zero_length_spring.hpp"

#include "brb/element/rotation.hpp"
#include "brb/material/parameter_error.hpp"

#include "support/finite_difference.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace brb::element {
namespace {

constexpr SpringStiffness kStopper{1e4, 2e3, 3e3, 5e6, 7e6, 11e6};

/// Forces of the spring when the nodes are displaced by `motion` (12: u_i, theta_i, u_j,
/// theta_j; rotations applied as spins from `base`).
Eigen::VectorXd forces_at(ZeroLengthSpring& spring, const std::vector<NodeConfiguration>& base,
                          const Eigen::VectorXd& motion) {
  std::vector<NodeConfiguration> nodes = base;
  for (int n = 0; n < 2; ++n) {
    nodes[n].position += motion.segment<3>(6 * n);
    nodes[n].rotation = rotation_from_vector(motion.segment<3>(6 * n + 3)) * nodes[n].rotation;
  }
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;
  std::string failure;
  EXPECT_TRUE(spring.evaluate(nodes, force, tangent, failure)) << failure;
  return force;
}

TEST(ZeroLengthSpring, TranslationsFollowHookesLawPerDof) {
  // Reference: f = k (u_j - u_i) per DOF, equal and opposite on the nodes; V = 1/2 k s^2.
  const Vector3 xi(0.0, 0.0, 0.0), xj(0.0, 0.0, 0.0);
  ZeroLengthSpring spring({0, 1}, xi, xj, kStopper);
  std::vector<NodeConfiguration> nodes{{xi, Matrix3::Identity()},
                                       {xj + Vector3(0.1, -0.2, 0.3), Matrix3::Identity()}};
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;
  std::string failure;
  ASSERT_TRUE(spring.evaluate(nodes, force, tangent, failure));
  EXPECT_NEAR(force[6], 1e4 * 0.1, 1e-9);
  EXPECT_NEAR(force[7], 2e3 * -0.2, 1e-9);
  EXPECT_NEAR(force[8], 3e3 * 0.3, 1e-9);
  EXPECT_NEAR((force.segment<3>(0) + force.segment<3>(6)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(spring.energy().stored, 0.5 * (1e4 * 0.01 + 2e3 * 0.04 + 3e3 * 0.09), 1e-9);
  EXPECT_DOUBLE_EQ(spring.energy().dissipated, 0.0);
}

TEST(ZeroLengthSpring, SmallTwistGivesTorqueKTimesTwist) {
  // Reference: for small relative rotations the moment is k_r (theta_j - theta_i).
  ZeroLengthSpring spring({0, 1}, Vector3::Zero(), Vector3::Zero(), kStopper);
  const double twist = 1e-6;
  std::vector<NodeConfiguration> nodes{
      {Vector3::Zero(), Matrix3::Identity()},
      {Vector3::Zero(), rotation_from_vector(Vector3(twist, 0.0, 0.0))}};
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;
  std::string failure;
  ASSERT_TRUE(spring.evaluate(nodes, force, tangent, failure));
  EXPECT_NEAR(force[9], 5e6 * twist, 1e-9);
  EXPECT_NEAR(force[3], -5e6 * twist, 1e-9);
}

TEST(ZeroLengthSpring, TangentIsConsistentAtFiniteRotations) {
  // Reference: central differences of the forces with respect to translations and spins.
  ZeroLengthSpring spring({0, 1}, Vector3(1.0, 2.0, 3.0), Vector3(1.0, 2.0, 3.5), kStopper);
  const std::vector<NodeConfiguration> base{
      {Vector3(1.1, 2.0, 2.9), rotation_from_vector(Vector3(0.3, -0.2, 0.1))},
      {Vector3(0.9, 2.2, 3.6), rotation_from_vector(Vector3(-0.1, 0.4, 0.25))}};
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;
  std::string failure;
  ASSERT_TRUE(spring.evaluate(base, force, tangent, failure));
  const Eigen::MatrixXd analytic = tangent;
  const auto forces = [&](const Eigen::VectorXd& motion) {
    return forces_at(spring, base, motion);
  };
  const Eigen::MatrixXd numeric =
      test::central_difference_jacobian(forces, Eigen::VectorXd::Zero(12).eval(), 1e-7);
  EXPECT_LT(test::relative_difference(analytic, numeric), 1e-6);
}

TEST(ZeroLengthSpring, RigidRotationOfBothNodesLeavesTheRotationalSpringUnloaded) {
  // Reference: the relative rotation R_j R_i^T of a rigidly rotated pair is the identity.
  ZeroLengthSpring spring({0, 1}, Vector3::Zero(), Vector3::Zero(), kStopper);
  const Matrix3 rigid = rotation_from_vector(Vector3(0.7, -0.4, 1.1));
  std::vector<NodeConfiguration> nodes{{Vector3::Zero(), rigid}, {Vector3::Zero(), rigid}};
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;
  std::string failure;
  ASSERT_TRUE(spring.evaluate(nodes, force, tangent, failure));
  EXPECT_LT(force.norm(), 1e-6);
}

TEST(ZeroLengthSpring, RejectsNegativeStiffness) {
  EXPECT_THROW(
      ZeroLengthSpring({0, 1}, Vector3::Zero(), Vector3::Zero(), {1.0, -1.0, 0.0, 0.0, 0.0, 0.0}),
      ParameterError);
}

} // namespace
} // namespace brb::element
