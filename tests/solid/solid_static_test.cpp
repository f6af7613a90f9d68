// Elastic acceptance checks of the 3D continuum model (issue 6), solved statically with the
// consistent tangent: the patch test on a distorted mesh, the bar's axial stiffness and the
// cantilever against beam theory.
#include "brb/material/isotropic_elastic_3d.hpp"
#include "brb/solid/solid_static.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <limits>

namespace brb::solid {
namespace {

constexpr double kSteelDensity = 7.85e-9; // tonne / mm^3

using ElasticModel = SolidModel<material::IsotropicElastic3D>;

ElasticModel elastic_model(const HexMesh& mesh, double E, double nu) {
  return ElasticModel(
      mesh, [=](double) { return material::IsotropicElastic3D(E, nu); }, kSteelDensity);
}

TEST(SolidStatic, PatchTestDistortedMeshGivesTheExactUniformStress) {
  // x = Q (I + A) X on the boundary, a large rotation Q included; the interior nodes of a
  // distorted 4 x 4 x 4 mesh start at X. Reference: the uniform field itself, S = C : E with
  // E = ((I + A)^T (I + A) - I) / 2 (St Venant-Kirchhoff, exact for a linear field).
  StructuredPrismMesh prism(Eigen::Vector3d(10.0, 12.0, 14.0), {4, 4, 4});
  prism.distort_interior_nodes(0.3, 2026);
  const HexMesh& mesh = prism.mesh();
  const double E = 210000.0, nu = 0.3;
  ElasticModel model = elastic_model(mesh, E, nu);
  Eigen::Matrix3d A;
  A << 2e-3, -1e-3, 5e-4, 1.5e-3, -1e-3, 2e-4, -3e-4, 8e-4, 1.2e-3;
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(1.1, Eigen::Vector3d(1, -2, 1).normalized()).matrix();
  const Eigen::Matrix3d F = Q * (Eigen::Matrix3d::Identity() + A);
  PrescribedDisplacements prescribed;
  Eigen::VectorXd exact(model.dof_count());
  for (int n = 0; n < mesh.node_count(); ++n) {
    const Eigen::Vector3d X = mesh.nodes.col(n);
    exact.segment<3>(3 * n) = F * X - X;
    if (!prism.is_interior(n))
      for (int i = 0; i < 3; ++i)
        prescribed.add(n, i, exact[3 * n + i]);
  }
  // start from the rigid rotation alone (the interior at X would invert elements)
  Eigen::VectorXd u(model.dof_count());
  for (int n = 0; n < mesh.node_count(); ++n)
    u.segment<3>(3 * n) = Q * mesh.nodes.col(n) - mesh.nodes.col(n);
  const SolidNewtonReport report =
      solve_static(model, u, prescribed, Eigen::VectorXd::Zero(model.dof_count()), {30, 1e-12});
  ASSERT_TRUE(report.converged) << report.failure;
  const material::Vector6 strain = green_lagrange_strain(F - Eigen::Matrix3d::Identity());
  const material::IsotropicElastic3D law(E, nu);
  const material::Vector6 stress = law.evaluate({}, strain).stress;
  for (int e = 0; e < model.element_count(); ++e)
    EXPECT_LT((model.stress()[e] - stress).norm(), 1e-10 * stress.norm()) << "element " << e;
  EXPECT_LT((u - exact).cwiseAbs().maxCoeff(), 1e-10 * 14.0);
  EXPECT_LT(model.energy().hourglass, 1e-12 * model.energy().internal);
}

/// A bar along x with roller supports (x_min face: ux = 0; two nodes stop the rigid motions
/// without restraining the lateral contraction) stretched by `elongation` on its x_max face;
/// returns the axial force (sum of the x_max reactions).
double bar_force(const Eigen::Vector3d& lengths, PrismDivisions divisions, double elongation,
                 double E, double nu) {
  const StructuredPrismMesh prism(lengths, divisions);
  ElasticModel model = elastic_model(prism.mesh(), E, nu);
  PrescribedDisplacements prescribed;
  for (int n : prism.face_nodes(PrismFace::x_min))
    prescribed.add(n, 0, 0.0);
  for (int n : prism.face_nodes(PrismFace::x_max))
    prescribed.add(n, 0, elongation);
  prescribed.add(prism.node_index(0, 0, 0), 1, 0.0);
  prescribed.add(prism.node_index(0, 0, 0), 2, 0.0);
  prescribed.add(prism.node_index(0, divisions.ny, 0), 2, 0.0);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(model.dof_count());
  Eigen::VectorXd reactions;
  const SolidNewtonReport report = solve_static(
      model, u, prescribed, Eigen::VectorXd::Zero(model.dof_count()), {30, 1e-12}, &reactions);
  EXPECT_TRUE(report.converged) << report.failure;
  if (!report.converged)
    return std::numeric_limits<double>::quiet_NaN();
  double force = 0.0;
  for (int n : prism.face_nodes(PrismFace::x_max))
    force += reactions[3 * n];
  return force;
}

TEST(SolidStatic, BarAxialStiffnessIsExact) {
  // Uniaxial stress of a St Venant-Kirchhoff bar: S11 = E E11 with E11 = (lambda^2 - 1) / 2,
  // lambda = 1 + delta / L, nominal force N = A0 lambda S11 (P11 = F11 S11). For a small
  // delta this is E A delta / L to first order.
  const Eigen::Vector3d lengths(200.0, 20.0, 30.0);
  const double E = 210000.0, nu = 0.3, area = 20.0 * 30.0;
  for (const double strain : {1e-4, 0.05}) {
    const double lambda = 1.0 + strain;
    const double exact = area * lambda * E * 0.5 * (lambda * lambda - 1.0);
    const double force = bar_force(lengths, {10, 2, 3}, strain * lengths[0], E, nu);
    EXPECT_NEAR(force / exact, 1.0, 1e-6) << "strain " << strain;
  }
  // and the linear stiffness itself
  const double delta = 1e-3;
  EXPECT_NEAR(bar_force(lengths, {10, 2, 3}, delta, E, nu) / (E * area * delta / lengths[0]), 1.0,
              1e-5);
}

TEST(SolidStatic, CantileverTipDeflectionWithinThreePercentOfBeamTheory) {
  // 40 elements along, 4 through the depth (and 2 across): L = 1000, h = 50, b = 40 mm,
  // clamped at x = 0 (all DOFs of the face), tip load P along y spread over the tip face with
  // the bilinear face weights. Reference: Timoshenko beam theory,
  //   delta = P L^3 / (3 E I) + P L / (k G A), k = 5/6 (a rectangle).
  const double L = 1000.0, h = 50.0, b = 40.0, E = 210000.0, nu = 0.3, P = 100.0;
  const StructuredPrismMesh prism(Eigen::Vector3d(L, h, b), {40, 4, 2});
  ElasticModel model = elastic_model(prism.mesh(), E, nu);
  PrescribedDisplacements prescribed;
  for (int n : prism.face_nodes(PrismFace::x_min))
    for (int i = 0; i < 3; ++i)
      prescribed.add(n, i, 0.0);
  Eigen::VectorXd load = Eigen::VectorXd::Zero(model.dof_count());
  const int ny = 4, nz = 2;
  for (int j = 0; j <= ny; ++j)
    for (int k = 0; k <= nz; ++k) {
      const double wj = (j == 0 || j == ny) ? 0.5 : 1.0;
      const double wk = (k == 0 || k == nz) ? 0.5 : 1.0;
      load[3 * prism.node_index(40, j, k) + 1] = P * wj * wk / (ny * nz);
    }
  ASSERT_NEAR(load.sum(), P, 1e-12 * P);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(model.dof_count());
  const SolidNewtonReport report = solve_static(model, u, prescribed, load, {30, 1e-11});
  ASSERT_TRUE(report.converged) << report.failure;
  double tip = 0.0;
  const std::vector<int> tip_nodes = prism.face_nodes(PrismFace::x_max);
  for (int n : tip_nodes)
    tip += u[3 * n + 1] / tip_nodes.size();
  const double I = b * h * h * h / 12.0, G = E / (2.0 * (1.0 + nu));
  const double beam = P * L * L * L / (3.0 * E * I) + P * L / (5.0 / 6.0 * G * b * h);
  RecordProperty("tip_over_beam_theory", std::to_string(tip / beam));
  EXPECT_NEAR(tip / beam, 1.0, 0.03);
}

} // namespace
} // namespace brb::solid
