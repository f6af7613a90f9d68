// One-element fixtures of the 3D continuum tests: a distorted hexahedron, its one-element
// mesh, its forces at given nodal positions and a tangent check by central differences.
#pragma once

#include "brb/solid/hex8.hpp"
#include "brb/solid/hex_mesh.hpp"
#include "brb/solid/solid_model.hpp"

#include "support/finite_difference.hpp"

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>

namespace brb::test {

/// A distorted element: the unit-cube corners scaled to 20 x 10 x 15 mm and moved randomly
/// by up to 15 % of the smallest side.
inline solid::NodeMatrix distorted_element(std::uint32_t seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-1.5, 1.5);
  solid::NodeMatrix x;
  for (int a = 0; a < 8; ++a) {
    x.col(a) = Eigen::Vector3d(10.0 * (solid::kNaturalCoordinates[a][0] + 1),
                               5.0 * (solid::kNaturalCoordinates[a][1] + 1),
                               7.5 * (solid::kNaturalCoordinates[a][2] + 1));
    for (int i = 0; i < 3; ++i)
      x(i, a) += uniform(generator);
  }
  return x;
}

inline solid::HexMesh one_element_mesh(const solid::NodeMatrix& x) {
  solid::HexMesh mesh;
  mesh.nodes = x;
  mesh.elements.push_back({0, 1, 2, 3, 4, 5, 6, 7});
  return mesh;
}

/// Forces of a one-element model at positions x (3 x 8, flattened).
template <class Law>
Eigen::VectorXd element_force(solid::SolidModel<Law>& model, const solid::NodeMatrix& X,
                              const Eigen::VectorXd& x) {
  Eigen::VectorXd u = x - Eigen::Map<const Eigen::VectorXd>(X.data(), 24);
  Eigen::VectorXd force;
  std::string reason;
  EXPECT_TRUE(model.evaluate(u, force, nullptr, reason)) << reason;
  return force;
}

/// The analytic tangent at positions x against central differences of the force.
template <class Law>
void expect_consistent_tangent(solid::SolidModel<Law>& model, const solid::NodeMatrix& X,
                               const solid::NodeMatrix& x, double tolerance) {
  const Eigen::VectorXd positions = Eigen::Map<const Eigen::VectorXd>(x.data(), 24);
  Eigen::VectorXd force;
  Eigen::SparseMatrix<double> tangent;
  std::string reason;
  ASSERT_TRUE(model.evaluate(positions - Eigen::Map<const Eigen::VectorXd>(X.data(), 24), force,
                             &tangent, reason));
  const Eigen::MatrixXd analytic(tangent);
  const Eigen::MatrixXd numeric = central_difference_jacobian(
      [&](const Eigen::VectorXd& p) { return element_force(model, X, p); }, positions, 1e-6);
  EXPECT_LT(relative_difference(analytic, numeric), tolerance);
}

} // namespace brb::test
