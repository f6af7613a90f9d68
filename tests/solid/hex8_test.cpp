// The one-point hexahedron: exact mean gradients, hourglass vectors orthogonal to linear
// fields, exact bending energy of a rectangular element, rigid-body invariance and a
// tangent checked by central differences (elastic and plastic).
#include "brb/material/isotropic_elastic_3d.hpp"
#include "brb/material/steel_damage_plasticity_3d.hpp"
#include "brb/solid/hex8.hpp"
#include "brb/solid/solid_model.hpp"

#include "support/finite_difference.hpp"
#include "support/hex_element.hpp"
#include "support/steel_fixtures.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <random>

namespace brb::solid {
namespace {

using test::distorted_element;
using test::one_element_mesh;

TEST(Hex8, MeanGradientsReproduceLinearFieldsExactly) {
  const NodeMatrix X = distorted_element(3);
  const Hex8Reference reference = hex8_reference(X);
  // sum_a b_a = 0 (constants) and sum_a X_a (x) b_a = I (linear fields): the isoparametric
  // identities, integrated exactly by 2x2x2 Gauss
  EXPECT_LT(reference.gradients.rowwise().sum().norm(), 1e-15);
  EXPECT_LT((X * reference.gradients.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  // hourglass vectors: orthogonal to constants and to the coordinates
  EXPECT_LT(reference.hourglass.rowwise().sum().norm(), 1e-14);
  EXPECT_LT((reference.hourglass * X.transpose()).norm(), 1e-13);
}

TEST(Hex8, HourglassVectorsAreDualToTheModesOfABox) {
  NodeMatrix X;
  for (int a = 0; a < 8; ++a)
    X.col(a) = Eigen::Vector3d(20.0 * kNaturalCoordinates[a][0], 5.0 * kNaturalCoordinates[a][1],
                               7.5 * kNaturalCoordinates[a][2]);
  const Hex8Reference reference = hex8_reference(X);
  EXPECT_NEAR(reference.volume, 40.0 * 10.0 * 15.0, 1e-9);
  EXPECT_TRUE(reference.half_lengths.isApprox(Eigen::Vector3d(20.0, 5.0, 7.5), 1e-14));
  Eigen::Matrix<double, 4, 8> h;
  for (int a = 0; a < 8; ++a) {
    const auto& s = kNaturalCoordinates[a];
    h.col(a) << s[1] * s[2], s[2] * s[0], s[0] * s[1], s[0] * s[1] * s[2];
  }
  EXPECT_LT((reference.hourglass * h.transpose() - Eigen::Matrix4d::Identity()).norm(), 1e-14);
}

TEST(Hex8, PureBendingEnergyOfABoxIsExact) {
  // u_x = kappa x y (pure bending about z of a beam along x, centred element): beam theory
  // stores 1/2 E kappa^2 int y^2 dV = 1/2 E kappa^2 V Ly^2 / 12, whatever nu (sigma_xx = E
  // kappa y, the other stresses zero). The centre strain is zero, so it is all hourglass.
  const double E = 210000.0, nu = 0.3, kappa = 1e-6;
  const Eigen::Vector3d lengths(40.0, 10.0, 15.0);
  NodeMatrix X;
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i)
      X(i, a) = 0.5 * lengths[i] * kNaturalCoordinates[a][i];
  NodeMatrix u = NodeMatrix::Zero();
  for (int a = 0; a < 8; ++a)
    u(0, a) = kappa * X(0, a) * X(1, a);
  const Hex8Reference reference = hex8_reference(X);
  const HourglassStiffness stiffness =
      hex8_hourglass_stiffness(reference, E, E / (2.0 * (1.0 + nu)));
  const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + hex8_displacement_gradient(reference, u);
  EXPECT_LT((F - Eigen::Matrix3d::Identity()).norm(), 1e-15);
  NodeMatrix force = NodeMatrix::Zero();
  const double energy = add_hex8_hourglass_response(reference, stiffness, F, u, force, nullptr);
  const double exact = 0.5 * E * kappa * kappa * reference.volume * lengths[1] * lengths[1] / 12.0;
  EXPECT_NEAR(energy / exact, 1.0, 1e-12);
  // the force is the gradient of the energy: f . u = 2 U for this quadratic energy
  EXPECT_NEAR((force.cwiseProduct(u)).sum() / (2.0 * exact), 1.0, 1e-12);
}

using test::element_force;
using test::expect_consistent_tangent;

TEST(Hex8, ElasticTangentMatchesCentralDifferencesUnderLargeDeformation) {
  // reference: central differences of the internal force (independent of the tangent code)
  const NodeMatrix X = distorted_element(11);
  SolidModel<material::IsotropicElastic3D> model(
      one_element_mesh(X), [](double) { return material::IsotropicElastic3D(210000.0, 0.3); },
      7.85e-9);
  // a large rotation, 10 % stretches and a visible hourglass deformation
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  NodeMatrix x = Q * (Eigen::Vector3d(1.1, 0.95, 1.05).asDiagonal() * X);
  std::mt19937 generator(5);
  std::uniform_real_distribution<double> uniform(-0.3, 0.3);
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i)
      x(i, a) += uniform(generator);
  expect_consistent_tangent(model, X, x, 1e-7);
}

TEST(Hex8, SteelTangentMatchesCentralDifferencesInAPlasticState) {
  const NodeMatrix X = distorted_element(12);
  const material::SteelParameters steel = test::linear_mixed_steel();
  SolidModel<material::SteelDamagePlasticity3D> model(
      one_element_mesh(X), [&](double lc) { return material::SteelDamagePlasticity3D(steel, lc); },
      7.85e-9);
  // 1 % stretch along x with shear: far past yield (fy / E = 0.13 %) from the virgin state
  Eigen::Matrix3d G = Eigen::Matrix3d::Identity();
  G(0, 0) = 1.01;
  G(0, 1) = 0.004;
  const NodeMatrix x = G * X;
  Eigen::VectorXd force;
  std::string reason;
  ASSERT_TRUE(model.evaluate(Eigen::Map<const Eigen::VectorXd>((x - X).eval().data(), 24), force,
                             nullptr, reason));
  EXPECT_GT(model.trial_states()[0].equivalent_plastic_strain, 1e-3);
  expect_consistent_tangent(model, X, x, 1e-6);
}

TEST(Hex8, RigidMotionsGiveNoForceAndRotateTheForces) {
  const NodeMatrix X = distorted_element(21);
  SolidModel<material::IsotropicElastic3D> model(
      one_element_mesh(X), [](double) { return material::IsotropicElastic3D(210000.0, 0.3); },
      7.85e-9);
  const Eigen::Matrix3d Q =
      Eigen::AngleAxisd(2.0, Eigen::Vector3d(-1, 0.5, 2).normalized()).matrix();
  const Eigen::Vector3d shift(3.0, -4.0, 5.0);
  const auto positions = [](const NodeMatrix& m) {
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(m.data(), 24));
  };
  // a rigid motion: no strain, no hourglass energy, no force
  const NodeMatrix rigid = (Q * X).colwise() + shift;
  const Eigen::VectorXd rigid_force = element_force(model, X, positions(rigid));
  // zero to the round-off of displacements ~ 30 mm: 1e-14 x E x V^(2/3) (about 4e-7 N)
  const double round_off = 1e-14 * 210000.0 * std::cbrt(3000.0 * 3000.0);
  EXPECT_LT(rigid_force.norm(), round_off);
  EXPECT_LT(model.trial_energy().hourglass, 1e-20 * model.references()[0].volume * 210000.0);
  // a deformation with hourglass content, then the same with a rotation superposed: the
  // forces rotate with it and the energies do not change (objectivity)
  NodeMatrix deformed = X;
  deformed.row(0) += 0.05 * X.row(1).cwiseProduct(X.row(2)) / 10.0;
  deformed.row(1) += 0.02 * X.row(0);
  const Eigen::VectorXd force = element_force(model, X, positions(deformed));
  const double hourglass = model.trial_energy().hourglass;
  EXPECT_GT(hourglass, 0.0);
  const Eigen::VectorXd rotated_force =
      element_force(model, X, positions((Q * deformed).colwise() + shift));
  Eigen::VectorXd expected(24);
  for (int a = 0; a < 8; ++a)
    expected.segment<3>(3 * a) = Q * force.segment<3>(3 * a);
  EXPECT_LT((rotated_force - expected).norm(), 1e-10 * force.norm());
  EXPECT_NEAR(model.trial_energy().hourglass / hourglass, 1.0, 1e-10);
}

TEST(Hex8, InvertedElementIsRejected) {
  NodeMatrix X = distorted_element(1);
  X.col(0).swap(X.col(6));
  EXPECT_THROW(hex8_reference(X), std::invalid_argument);
}

} // namespace
} // namespace brb::solid
