// Co-rotational kinematics: local deformations free of rigid-body motion and the
// consistent (geometric) tangent against finite differences.
#include "brb/element/corotational_frame.hpp"
#include "brb/element/rotation.hpp"

#include "support/finite_difference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace brb::element {
namespace {

struct TwoNodes {
  NodeConfiguration i, j;
};

/// Applies a global increment d_g = [du_i, dw_i, du_j, dw_j] (spins update the triads).
TwoNodes moved(const TwoNodes& nodes, const GlobalVector& increment) {
  TwoNodes result = nodes;
  result.i.position += increment.segment<3>(0);
  result.i.rotation = rotation_from_vector(increment.segment<3>(3)) * nodes.i.rotation;
  result.j.position += increment.segment<3>(6);
  result.j.rotation = rotation_from_vector(increment.segment<3>(9)) * nodes.j.rotation;
  return result;
}

TEST(Rotation, ExponentialAndLogarithmAreInverse) {
  // Reference: log(exp(theta)) = theta for |theta| < pi; J^-1 against finite differences.
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Vector3 theta =
        Vector3(unit(random), unit(random), unit(random)) * (trial % 2 ? 1.7 : 1e-4 * (trial % 7));
    EXPECT_LT((vector_from_rotation(rotation_from_vector(theta)) - theta).norm(), 1e-12);
    const Matrix3 rotation = rotation_from_vector(theta);
    EXPECT_LT((rotation.transpose() * rotation - Matrix3::Identity()).norm(), 1e-14);
    // d theta = J^-1 dw when R <- exp(dw) R
    const double h = 1e-7;
    Matrix3 numeric;
    for (int k = 0; k < 3; ++k) {
      const Vector3 spin = h * Vector3::Unit(k);
      numeric.col(k) = (vector_from_rotation(rotation_from_vector(spin) * rotation) -
                        vector_from_rotation(rotation_from_vector(-spin) * rotation)) /
                       (2.0 * h);
    }
    EXPECT_LT((inverse_left_jacobian(theta) - numeric).norm(), 1e-7) << theta.transpose();
  }
}

TEST(Rotation, DerivativeOfInverseJacobianTransposeMatchesFiniteDifferences) {
  const Vector3 moment(3.0, -1.0, 2.0);
  for (const Vector3& theta : {Vector3(0.3, -0.2, 0.5), Vector3(1e-3, 2e-3, -1e-3),
                               Vector3(2.0, 0.5, -1.0), Vector3::Zero().eval()}) {
    const auto g = [&](const Vector3& t) {
      return Eigen::Vector3d(inverse_left_jacobian(t).transpose() * moment);
    };
    const Eigen::MatrixXd numeric = test::central_difference_jacobian(g, theta, 1e-6);
    EXPECT_LT((inverse_left_jacobian_transpose_derivative(theta, moment) - numeric).norm(), 1e-8);
  }
}

class CorotationalFrameTest : public ::testing::Test {
protected:
  const Vector3 start{100.0, 50.0, -20.0};
  const Vector3 end{1100.0, 250.0, 80.0};
  CorotationalFrame frame{start, end, Vector3(0.2, 0.3, 1.0)};
  TwoNodes initial{{start, Matrix3::Identity()}, {end, Matrix3::Identity()}};
};

TEST_F(CorotationalFrameTest, RigidBodyMotionGivesNoDeformation) {
  // Reference: a rigid rotation Q and translation c maps x -> Q x + c, R -> Q R; the local
  // deformations must stay zero (to round-off) for 90 degrees about each axis and for a
  // combined rotation.
  const double quarter = std::numbers::pi / 2.0;
  for (const Vector3& axis : {Vector3(quarter, 0, 0), Vector3(0, quarter, 0),
                              Vector3(0, 0, quarter), Vector3(1.2, -0.7, 2.1)}) {
    const Matrix3 q = rotation_from_vector(axis);
    const Vector3 shift(13.0, -7.0, 3.0);
    TwoNodes rotated{{q * start + shift, q}, {q * end + shift, q}};
    ASSERT_TRUE(frame.update(rotated.i, rotated.j));
    EXPECT_LT(frame.local_deformation().norm(), 1e-12 * frame.initial_length());
  }
}

TEST_F(CorotationalFrameTest, TangentMatchesFiniteDifferencesOfInternalForce) {
  // Reference: central differences of B^T f_l (translations additive, rotations by spins)
  // at deformed configurations with arbitrary local forces and local tangent.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    GlobalVector deformation;
    for (int k = 0; k < 12; ++k)
      deformation[k] = unit(random) * (k % 6 < 3 ? 80.0 : 0.6);
    const TwoNodes current = moved(initial, deformation);
    LocalVector local_force;
    for (int k = 0; k < 7; ++k)
      local_force[k] = unit(random) * (k == 0 ? 1e5 : 1e7);
    LocalMatrix local_tangent;
    for (int r = 0; r < 7; ++r)
      for (int c = 0; c < 7; ++c)
        local_tangent(r, c) = unit(random) * 1e6;

    ASSERT_TRUE(frame.update(current.i, current.j));
    const LocalVector local_deformation = frame.local_deformation();
    GlobalVector force;
    GlobalMatrix tangent;
    frame.global_response(local_force, local_tangent, force, tangent);

    // f_g(d) with f_l = f_l0 + K_l (d_l(d) - d_l0): the tangent of that map is the consistent one.
    const auto internal_force = [&](const GlobalVector& increment) {
      CorotationalFrame probe = frame;
      const TwoNodes perturbed = moved(current, increment);
      EXPECT_TRUE(probe.update(perturbed.i, perturbed.j));
      const LocalVector f =
          local_force + local_tangent * (probe.local_deformation() - local_deformation);
      GlobalVector g;
      GlobalMatrix unused;
      probe.global_response(f, local_tangent, g, unused);
      return g;
    };
    const Eigen::MatrixXd numeric =
        test::central_difference_jacobian(internal_force, GlobalVector::Zero().eval(), 1e-6);
    EXPECT_LT(test::relative_difference(tangent, numeric), 1e-6) << "trial " << trial;
  }
}

} // namespace
} // namespace brb::element
