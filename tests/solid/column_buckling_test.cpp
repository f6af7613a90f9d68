// A slender column of hexahedra buckles at the Euler load (issue 6, elastic checks). Static
// path: Newton under displacement control of the top face's axial displacement.
#include "brb/material/isotropic_elastic_3d.hpp"
#include "brb/solid/solid_static.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace brb::solid {
namespace {

TEST(SolidColumn, FixedGuidedColumnBucklesAtTheEulerLoad) {
  // L = 1000 mm, section 20 (y) x 30 (z) mm, 40 x 4 x 2 elements. Base clamped; the top face
  // is pushed down uniformly along x and is free to sway in y and z but cannot rotate (all its
  // nodes share ux): a fixed-guided column, P_E = pi^2 E I / L^2 (effective length L;
  // Timoshenko & Gere, Theory of Elastic Stability, sec. 2.2), I = 30 x 20^3 / 12. The
  // geometry carries the first buckling mode as imperfection, w(x) = e0 (1 - cos(pi x / L)) / 2
  // with e0 = L / 1000. Past buckling the force of the imperfect column approaches P_E from
  // below (P / P_E = 1 - e0 / a for a top sway a) and the elastica adds about
  // (pi a / L)^2 / 16 at a = L / 40: both well inside the 5 % asked.
  const double L = 1000.0, h = 20.0, b = 30.0, E = 210000.0, nu = 0.3, e0 = L / 1000.0;
  const StructuredPrismMesh prism(Eigen::Vector3d(L, h, b), {40, 4, 2});
  HexMesh mesh = prism.mesh();
  for (int n = 0; n < mesh.node_count(); ++n)
    mesh.nodes(1, n) += 0.5 * e0 * (1.0 - std::cos(std::numbers::pi * mesh.nodes(0, n) / L));
  SolidModel<material::IsotropicElastic3D> model(
      mesh, [=](double) { return material::IsotropicElastic3D(E, nu); }, 7.85e-9);
  const double I = b * h * h * h / 12.0;
  const double euler = std::numbers::pi * std::numbers::pi * E * I / (L * L);
  const double euler_shortening = euler * L / (E * b * h);

  const std::vector<int> base = prism.face_nodes(PrismFace::x_min);
  const std::vector<int> top = prism.face_nodes(PrismFace::x_max);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(model.dof_count());
  const Eigen::VectorXd no_load = Eigen::VectorXd::Zero(model.dof_count());
  const int steps = 40;
  double force = 0.0, sway = 0.0, largest_force = 0.0;
  for (int step = 1; step <= steps; ++step) {
    const double shortening = 2.5 * euler_shortening * step / steps;
    PrescribedDisplacements prescribed;
    for (int n : base)
      for (int i = 0; i < 3; ++i)
        prescribed.add(n, i, 0.0);
    for (int n : top)
      prescribed.add(n, 0, -shortening);
    Eigen::VectorXd reactions;
    const SolidNewtonReport report =
        solve_static(model, u, prescribed, no_load, {40, 1e-10}, &reactions);
    ASSERT_TRUE(report.converged) << "step " << step << ": " << report.failure;
    force = 0.0;
    sway = 0.0;
    for (int n : top) {
      force -= reactions[3 * n];
      sway += u[3 * n + 1] / top.size();
    }
    largest_force = std::max(largest_force, force);
  }
  RecordProperty("force_over_euler", std::to_string(force / euler));
  RecordProperty("sway_over_imperfection", std::to_string(sway / e0));
  // buckled: the sway is many times the imperfection, the force at the Euler load
  EXPECT_GT(sway / e0, 10.0);
  EXPECT_NEAR(force / euler, 1.0, 0.05);
  EXPECT_NEAR(largest_force / euler, 1.0, 0.05);
}

} // namespace
} // namespace brb::solid
