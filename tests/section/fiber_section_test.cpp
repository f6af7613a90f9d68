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

// Split halves (FiberSection::split_halves). A rectangle of width b along y and depth h along
// z, n equal cells along y: the cell-centre rule gives sum A y^2 = h b^3 / 12 (1 - 1/n^2), and
// each half (width b/2, n/2 cells) about its own centroid h (b/2)^3 / 12 (1 - 4/n^2).
TEST(FiberSection, FullySplitSectionBendsAsItsTwoHalves) {
  const auto steel = test::linear_mixed_steel();
  const double b = 30.0, h = 10.0;
  const int n = 6;
  FiberSection section(mesh_rectangle(b, h, n, 4), SteelUniaxial(steel, 1.0), 8e4);
  const double E = steel.youngs_modulus;
  const double whole = h * b * b * b / 12.0 * (1.0 - 1.0 / (n * n));
  const double halves = 2.0 * h * std::pow(b / 2.0, 3) / 12.0 * (1.0 - 4.0 / (n * n));
  EXPECT_NEAR(section.evaluate(SectionVector::Zero()).tangent(2, 2), E * whole, 1e-6 * E * whole);
  section.commit();
  section.split_halves({1.0, 0.0});
  const auto& split = section.evaluate(SectionVector(1e-5, 0.0, 0.0));
  EXPECT_NEAR(split.tangent(2, 2), E * halves, 1e-9 * E * whole);
  EXPECT_NEAR(split.tangent(2, 2), 0.25 * E * whole * (1.0 - 4.0 / (n * n)) / (1.0 - 1.0 / (n * n)),
              1e-9 * E * whole);
  // the other direction and the axial stiffness are untouched; the halves stay symmetric
  EXPECT_NEAR(split.tangent(0, 0), E * b * h, 1e-9 * E * b * h);
  EXPECT_NEAR(split.tangent(1, 1), E * section.layout().second_moment_y(), 1e-6);
  EXPECT_NEAR(split.tangent(0, 2), 0.0, 1e-9 * E * b * h);
  EXPECT_EQ(section.split_fractions()[0], 1.0);
}

TEST(FiberSection, PartlySplitStiffnessFollowsTheLeverAlgebra) {
  // Reference: sum A (z - phi c)^2 = I - (2 phi - phi^2) sum A c^2, sum A c^2 = A (h/4)^2 for
  // the halves of a rectangle of depth h (centroids at +-h/4), whatever the cells along z.
  const auto steel = test::linear_mixed_steel();
  const double b = 12.0, h = 40.0, phi = 0.5;
  FiberSection section(mesh_rectangle(b, h, 3, 8), SteelUniaxial(steel, 1.0), 8e4);
  section.evaluate(SectionVector::Zero());
  section.commit();
  section.split_halves({0.0, phi});
  const double lever_squares = b * h * (h / 4.0) * (h / 4.0);
  const double expected = steel.youngs_modulus * (section.layout().second_moment_y() -
                                                  (2 * phi - phi * phi) * lever_squares);
  EXPECT_NEAR(section.evaluate(SectionVector::Zero()).tangent(1, 1), expected, 1e-9 * expected);
}

TEST(FiberSection, SplittingKeepsTheFiberStressesAndEnergiesAndLeavesTheHalvesSelfEquilibrated) {
  // Bent elastically to kappa_z, then split: every fiber keeps its strain and stress, M_z
  // falls to the halves' own moments E I_halves kappa_z, and the energies do not jump.
  // Unbent to zero deformation, the halves keep opposite axial forces E A_h c kappa (c = b/4)
  // that make no resultant, storing E kappa^2 sum A c^2 / 2 (theory: the moment of the
  // halves' forces about the centroid, which the crack no longer transfers).
  const auto steel = test::linear_mixed_steel();
  const double b = 20.0, h = 10.0, kappa = 2e-5; // outer fiber 2e-4 < yield strain 1.3e-3
  FiberSection section(mesh_rectangle(b, h, 8, 2), SteelUniaxial(steel, 1.0), 8e4);
  section.evaluate(SectionVector(0.0, 0.0, kappa));
  section.commit();
  const std::vector<double> stresses = section.fiber_stresses();
  const double stored = section.stored_energy(), work = section.stress_work();
  section.split_halves({1.0, 0.0});
  for (std::size_t i = 0; i < stresses.size(); ++i)
    EXPECT_NEAR(section.fiber_stresses()[i], stresses[i], 1e-12 * steel.yield_stress);
  EXPECT_NEAR(section.stored_energy(), stored, 1e-12 * stored);
  EXPECT_NEAR(section.stress_work(), work, 1e-12 * work);
  const double E = steel.youngs_modulus;
  const double halves = 2.0 * h * std::pow(b / 2.0, 3) / 12.0 * (1.0 - 4.0 / 64.0);
  EXPECT_NEAR(section.last_response().force[2], E * halves * kappa, 1e-9 * E * halves * kappa);

  const auto& unbent = section.evaluate(SectionVector::Zero());
  const double force_scale = E * b * h * kappa * b;
  EXPECT_NEAR(unbent.force.norm(), 0.0, 1e-12 * force_scale);
  const double locked = 0.5 * E * kappa * kappa * b * h * (b / 4.0) * (b / 4.0);
  EXPECT_NEAR(section.stored_energy(), locked, 1e-9 * locked);
  // elastic and linear: the trapezoidal stress work is exact, so it equals the stored energy
  EXPECT_NEAR(section.stress_work(), section.stored_energy(), 1e-9 * stored);
  EXPECT_NEAR(misfit_of(section), 0.0, 1e-9 * stored);
}

TEST(FiberSection, SplitTangentMatchesFiniteDifferencesPastYield) {
  // Reference: central differences of the resultants of the split section (plastic fibers).
  const auto steel = test::linear_mixed_steel();
  FiberSection section(mesh_rectangle(20.0, 10.0, 6, 4), SteelUniaxial(steel, 1.0), 8e4);
  section.evaluate(SectionVector(1e-4, 3e-4, -2e-4));
  section.commit();
  section.split_halves({0.6, 0.8});
  const SectionVector deformation(-2e-4, 5e-4, -4e-4);
  const SectionMatrix tangent = section.evaluate(deformation).tangent;
  const std::array<double, 3> steps{1e-9, 1e-10, 1e-10};
  for (int j = 0; j < 3; ++j) {
    SectionVector ahead = deformation, behind = deformation;
    ahead[j] += steps[j];
    behind[j] -= steps[j];
    const SectionVector force_ahead = section.evaluate(ahead).force;   // evaluate returns a
    const SectionVector force_behind = section.evaluate(behind).force; // reference: copy it
    const SectionVector difference = (force_ahead - force_behind) / (2.0 * steps[j]);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(tangent(i, j), difference[i], 1e-5 * tangent.norm()) << i << ", " << j;
  }
}

TEST(FiberSection, SplitFractionsMustGrowWithinZeroToOne) {
  const auto steel = test::linear_mixed_steel();
  FiberSection section(mesh_rectangle(20.0, 10.0, 2, 2), SteelUniaxial(steel, 1.0), 8e4);
  section.split_halves({0.5, 0.0});
  EXPECT_THROW(section.split_halves({0.4, 0.0}), std::invalid_argument); // a crack does not heal
  EXPECT_THROW(section.split_halves({0.5, 1.5}), std::invalid_argument);
  EXPECT_THROW(section.split_halves({0.5, -0.1}), std::invalid_argument);
  EXPECT_NO_THROW(section.split_halves({1.0, 1.0}));
}

} // namespace
} // namespace brb::section
