// Fiber meshers and fiber section resultants against closed-form section properties.
#include "brb/section/fiber_section.hpp"

#include "brb/material/steel_uniaxial.hpp"

#include "support/finite_difference.hpp"
#include "support/steel_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace brb::section {
namespace {

using material::SteelUniaxial;
constexpr double pi = std::numbers::pi;

TEST(FiberLayout, RectangleMatchesClosedFormProperties) {
  // Reference: A = b h, I_y = b h^3 / 12 (about y, depth h along z), cell-centre rule error
  // I = b h^3/12 (1 - 1/n^2).
  const FiberLayout layout = mesh_rectangle(30.0, 10.0, 6, 20);
  EXPECT_NEAR(layout.total_area(), 300.0, 1e-9);
  EXPECT_NEAR(layout.second_moment_y(), 30.0 * 1000.0 / 12.0 * (1.0 - 1.0 / 400.0), 1e-9);
  EXPECT_NEAR(layout.second_moment_z(), 10.0 * 27000.0 / 12.0 * (1.0 - 1.0 / 36.0), 1e-9);
  // Saint-Venant: J of a square a^4 x 0.1406 (Timoshenko & Goodier, table), b/t = 3: 0.263 b t^3
  EXPECT_NEAR(rectangle_torsion_constant(10.0, 10.0), 0.1406 * 1e4, 0.0005 * 1e4);
  EXPECT_NEAR(rectangle_torsion_constant(30.0, 10.0), 0.263 * 30.0 * 1000.0, 0.001 * 30e3);
}

TEST(FiberLayout, CircleAndTubesMatchClosedFormProperties) {
  // Reference: circle A = pi d^2/4, I = pi d^4/64; tube the difference of two circles;
  // rectangular tube the difference of two rectangles (up to the cell-centre rule).
  const FiberLayout circle = mesh_circle(22.0, 6, 24);
  EXPECT_NEAR(circle.total_area(), pi * 22.0 * 22.0 / 4.0, 1e-9);
  EXPECT_NEAR(circle.second_moment_y(), pi * std::pow(22.0, 4) / 64.0, 1e-6);
  EXPECT_NEAR(circle.second_moment_z(), pi * std::pow(22.0, 4) / 64.0, 1e-6);

  const FiberLayout tube = mesh_circular_tube(115.0, 3.0, 2, 36);
  EXPECT_NEAR(tube.total_area(), pi * (115.0 * 115.0 - 109.0 * 109.0) / 4.0, 1e-9);
  EXPECT_NEAR(tube.second_moment_y(), pi * (std::pow(115.0, 4) - std::pow(109.0, 4)) / 64.0,
              1e-6 * std::pow(115.0, 4));

  const FiberLayout box = mesh_rectangular_tube(355.6, 355.6, 7.9, 40, 4);
  const double inner = 355.6 - 2 * 7.9;
  EXPECT_NEAR(box.total_area(), 355.6 * 355.6 - inner * inner, 1e-6);
  const double exact_i = (std::pow(355.6, 4) - std::pow(inner, 4)) / 12.0;
  EXPECT_NEAR(box.second_moment_y(), exact_i, 1e-3 * exact_i);
  EXPECT_NEAR(box.second_moment_z(), exact_i, 1e-3 * exact_i);
}

TEST(FiberLayout, CruciformCountsTheCrossingOnce) {
  // Reference: A = t (w + d - t); I_y = t d^3/12 + (w - t) t^3/12 (plate along z plus arms),
  // up to the cell-centre rule (about 0.2 % here).
  const double w = 247.65, d = 104.775, t = 38.1; // UCSD G3 core, in mm
  const FiberLayout layout = mesh_cruciform(w, d, t, 40, 12);
  EXPECT_NEAR(layout.total_area(), t * (w + d - t), 1e-6);
  const double exact_iy = t * std::pow(d, 3) / 12.0 + (w - t) * std::pow(t, 3) / 12.0;
  EXPECT_NEAR(layout.second_moment_y(), exact_iy, 5e-3 * exact_iy);
}

TEST(FiberSection, ElasticStiffnessIsEAandEI) {
  // Reference: elastic section, N = E A e0, M_y = E I_y kappa_y, M_z = E I_z kappa_z.
  const auto steel = test::linear_mixed_steel();
  FiberSection section(mesh_rectangle(30.0, 10.0, 6, 20), SteelUniaxial(steel, 1.0), 80769.0);
  const auto& response = section.evaluate(SectionVector(1e-4, 2e-6, -3e-7));
  const FiberLayout& layout = section.layout();
  const double E = steel.youngs_modulus;
  EXPECT_NEAR(response.force[0], E * layout.total_area() * 1e-4, 1e-6);
  EXPECT_NEAR(response.force[1], E * layout.second_moment_y() * 2e-6, 1e-6);
  EXPECT_NEAR(response.force[2], E * layout.second_moment_z() * -3e-7, 1e-6);
  EXPECT_NEAR(response.tangent(0, 1), 0.0, 1e-6); // symmetric section: no coupling
}

TEST(FiberSection, PlasticMomentOfRectangleAndCircle) {
  // Reference: perfectly plastic fibers at large curvature give the plastic moment
  // M_p = fy b h^2 / 4 (rectangle; exact for an even fiber count) and fy d^3 / 6 (circle).
  const auto steel = test::linear_mixed_steel(0.0, 0.0);
  FiberSection rectangle(mesh_rectangle(30.0, 10.0, 2, 40), SteelUniaxial(steel, 1.0), 8e4);
  EXPECT_NEAR(rectangle.evaluate(SectionVector(0.0, 0.05, 0.0)).force[1],
              steel.yield_stress * 30.0 * 100.0 / 4.0, 1e-6);
  FiberSection circle(mesh_circle(22.0, 16, 64), SteelUniaxial(steel, 1.0), 8e4);
  const double circle_mp = steel.yield_stress * std::pow(22.0, 3) / 6.0;
  EXPECT_NEAR(std::abs(circle.evaluate(SectionVector(0.0, 0.0, 0.05)).force[2]), circle_mp,
              0.01 * circle_mp);
}

TEST(FiberSection, TangentMatchesFiniteDifferencesAndCommitKeepsHistory) {
  // Reference: central differences of the resultants from the same committed state.
  const auto steel = test::chaboche_voce_steel();
  FiberSection section(mesh_circle(22.0, 4, 16), SteelUniaxial(steel, 1.0), 8e4);
  const SectionVector loaded(2e-3, 1e-4, -5e-5);
  section.evaluate(loaded);
  section.commit();
  const SectionVector next(2.5e-3, 1.3e-4, -4e-5);
  const SectionMatrix tangent = section.evaluate(next).tangent;
  const auto force_of = [&](const SectionVector& e) { return section.evaluate(e).force; };
  const Eigen::MatrixXd numeric = test::central_difference_jacobian(force_of, next, 1e-9);
  EXPECT_LT(test::relative_difference(tangent, numeric), 1e-6);
  // trial evaluations do not change the committed history
  section.revert_to_committed();
  const auto again = section.evaluate(loaded).force;
  section.revert_to_committed();
  EXPECT_NEAR((section.evaluate(loaded).force - again).norm(), 0.0, 1e-9);
}

} // namespace
} // namespace brb::section
