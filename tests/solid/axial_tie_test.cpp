// AxialTie, the stopper of the 3D brace: forces of a spring between two node sets' mean axial
// displacements, its energy, and its frequency bound against the eigenvalues of M^-1 K.
#include "brb/solid/axial_tie.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <stdexcept>

namespace brb::solid {
namespace {

TEST(AxialTie, SpringBetweenMeanAxialDisplacements) {
  // set A = nodes {0, 1}, set B = nodes {2, 3, 4}; u_x = (1, 3 | 0.5, 0.5, 2): e = 2 - 1 = 1.
  const double k = 50.0;
  AxialTie tie({0, 1}, {2, 3, 4}, k);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(15), force = Eigen::VectorXd::Zero(15);
  u[0] = 1.0;
  u[3] = 3.0;
  u[6] = 0.5;
  u[9] = 0.5;
  u[12] = 2.0;
  u[1] = 7.0; // lateral motion does not stretch it
  std::string reason;
  ASSERT_TRUE(tie.add_force(u, force, reason));
  EXPECT_DOUBLE_EQ(force[0], k * 1.0 / 2.0);
  EXPECT_DOUBLE_EQ(force[3], k * 1.0 / 2.0);
  for (int node : {2, 3, 4})
    EXPECT_DOUBLE_EQ(force[3 * node], -k * 1.0 / 3.0);
  EXPECT_NEAR(force.sum(), 0.0, 1e-12); // no net force
  EXPECT_EQ(tie.stored_energy(), 0.0);  // not committed yet
  tie.commit();
  EXPECT_DOUBLE_EQ(tie.stored_energy(), 0.5 * k);
  EXPECT_DOUBLE_EQ(tie.force(), k);
  EXPECT_EQ(tie.dissipated_energy(), 0.0);
}

TEST(AxialTie, FrequencyBoundIsTheLargestEigenvalueOfItsStiffness) {
  // Independent computation: the stiffness k g g^T assembled on the x DOFs of 5 nodes of
  // unequal masses, and the largest eigenvalue of M^-1/2 K M^-1/2 (Eigen's symmetric solver).
  const double k = 1e4;
  AxialTie tie({0, 1}, {2, 3, 4}, k);
  Eigen::VectorXd mass(15);
  for (int i = 0; i < 15; ++i)
    mass[i] = 1e-3 * (1.0 + 0.37 * (i / 3));
  Eigen::VectorXd g = Eigen::VectorXd::Zero(5);
  g << 0.5, 0.5, -1.0 / 3.0, -1.0 / 3.0, -1.0 / 3.0;
  Eigen::VectorXd scaled(5);
  for (int n = 0; n < 5; ++n)
    scaled[n] = g[n] / std::sqrt(mass[3 * n]);
  const Eigen::MatrixXd stiffness = k * scaled * scaled.transpose();
  const double largest =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(stiffness).eigenvalues().maxCoeff();
  EXPECT_NEAR(tie.frequency_bound_squared(mass) / largest, 1.0, 1e-12);
  EXPECT_THROW(AxialTie({}, {1}, k), std::invalid_argument);
  EXPECT_THROW(AxialTie({0}, {1}, 0.0), std::invalid_argument);
}

} // namespace
} // namespace brb::solid
