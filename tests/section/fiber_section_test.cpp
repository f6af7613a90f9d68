// Fiber meshers and fiber section resultants against closed-form section properties.
#include "brb/section/fiber_section.hpp"

#include "brb/material/steel_uniaxial.hpp"

#include "support/finite_difference.hpp"
#include "support/steel_fixtures.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

namespace brb::section {
namespace {

/// The section's stress work minus its laws' energies (what CorotBeam3D reports per unit
/// length as its integration misfit).
template <class Section> double misfit_of(const Section& section) {
  return section.stress_work() - section.stored_energy() - section.dissipated_energy();
}

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

TEST(FiberSection, StressWorkIsTheTrapezoidalRuleAndItsMisfitTheKinkOfFirstYield) {
  // Reference (by hand): one fiber of area A, E = 210000, fy = 275, linear kinematic
  // hardening H (uniaxial tangent Et = E H / (E + H)), strained from 0 to 3 eps_y in one
  // step. The law's energy is the exact integral along the path, elastic to eps_y and then
  // on the hardening branch: W = fy eps_y / 2 + (fy + s) / 2 (3 eps_y - eps_y), s the end
  // stress; the trapezoidal work is s / 2 3 eps_y. The misfit is their difference, and a
  // second step on the hardening branch (linear) adds none.
  const auto steel = test::linear_mixed_steel(15000.0, 0.0);
  const double area = 7.0;
  FiberLayout one_fiber;
  one_fiber.y = {0.0};
  one_fiber.z = {0.0};
  one_fiber.area = {area};
  FiberSection section(one_fiber, SteelUniaxial(steel, 1.0), 8e4);
  const double E = steel.youngs_modulus, fy = steel.yield_stress;
  const double yield_strain = fy / E;
  const double tangent = E * 15000.0 / (E + 15000.0);
  const double end_stress = fy + tangent * 2.0 * yield_strain;
  section.evaluate(SectionVector(3.0 * yield_strain, 0.0, 0.0));
  EXPECT_NEAR(section.fiber_stresses()[0], end_stress, 1e-9);
  const double trapezoid = 0.5 * end_stress * 3.0 * yield_strain * area;
  const double exact =
      (0.5 * fy * yield_strain + 0.5 * (fy + end_stress) * 2.0 * yield_strain) * area;
  EXPECT_NEAR(section.stress_work(), trapezoid, 1e-12 * trapezoid);
  EXPECT_NEAR(section.stored_energy() + section.dissipated_energy(), exact, 1e-9 * exact);
  EXPECT_NEAR(misfit_of(section), trapezoid - exact, 1e-9 * exact);
  EXPECT_GT(std::abs(trapezoid - exact), 0.05 * exact); // the kink is not small here

  // committed: a step along the hardening branch (stress linear in strain) adds no misfit
  section.commit();
  const double misfit_after_yield = misfit_of(section);
  section.evaluate(SectionVector(5.0 * yield_strain, 0.0, 0.0));
  EXPECT_NEAR(misfit_of(section), misfit_after_yield, 1e-9 * exact);
  // a reverted trial leaves the committed work
  section.revert_to_committed();
  EXPECT_NEAR(section.stress_work(), trapezoid, 1e-12 * trapezoid);
}

TEST(FiberSection, IntegrationMisfitFallsWithTheSquareOfTheStep) {
  // Reference: the trapezoidal rule's error over a kinked path; a cycle to +-4 eps_y in n
  // equal steps (nonlinear Chaboche and Voce hardening, bending too): the misfit's size
  // falls like (1 / n)^2 (ratio about 4 per halving; bounds 2.5..6), and stays a small part
  // of the work.
  const auto steel = test::chaboche_voce_steel();
  const double yield_strain = steel.yield_stress / steel.youngs_modulus;
  const auto misfit_in = [&](int steps) {
    FiberSection section(mesh_rectangle(20.0, 10.0, 2, 10), SteelUniaxial(steel, 1.0), 8e4);
    const std::array<double, 3> turns{4.0, -4.0, 0.0};
    double at = 0.0;
    for (const double turn : turns) {
      const double target = turn * yield_strain;
      const double from = at;
      for (int k = 1; k <= steps; ++k) {
        at = from + (target - from) * k / steps;
        section.evaluate(SectionVector(at, 0.3 * at / 10.0, 0.0));
        section.commit();
      }
    }
    return std::abs(misfit_of(section)) / std::abs(section.stress_work());
  };
  const double coarse = misfit_in(10), fine = misfit_in(20), finer = misfit_in(40);
  EXPECT_GT(coarse / fine, 2.5);
  EXPECT_LT(coarse / fine, 6.0);
  EXPECT_GT(fine / finer, 2.5);
  EXPECT_LT(fine / finer, 6.0);
  EXPECT_LT(coarse, 0.05);
}

} // namespace
} // namespace brb::section
