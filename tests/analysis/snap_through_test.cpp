// The solver passes a snap-through under displacement control (a limit point of the
// controlled path) by pseudo-transient continuation, and books the energy it releases.
#include "brb/analysis/static_analysis.hpp"
#include "brb/element/corot_truss.hpp"
#include "brb/material/steel_uniaxial.hpp"

#include <gtest/gtest.h>

namespace brb::analysis {
namespace {

using Truss = element::CorotTruss<material::SteelUniaxial>;

material::SteelParameters elastic_steel() {
  material::SteelParameters steel;
  steel.youngs_modulus = 210000.0;
  steel.poissons_ratio = 0.3;
  steel.yield_stress = 1e9; // elastic throughout
  return steel;
}

TEST(SnapThrough, SoftSpringOverAShallowTrussSnapsAndReleasesEnergy) {
  // Reference: a shallow two-bar (von Mises) truss, half-span 1000 mm, rise 50 mm, loaded at
  // its apex through a soft spring (5 N/mm) whose far end is driven down. The truss' force
  // on its apex peaks and then falls faster than the spring can follow: the controlled path
  // has a limit point and the apex must jump through to the inverted, stable configuration.
  // Everything is elastic, so the work done equals the stored energy plus what the jump
  // released (the drop of stored energy across the jump, absorbed by the pseudo-viscosity
  // that carries it).
  model::Model model;
  const int left = model.add_node({-1000.0, 0.0, 0.0});
  const int right = model.add_node({1000.0, 0.0, 0.0});
  const int apex = model.add_node({0.0, 50.0, 0.0});
  const int driver = model.add_node({0.0, 1050.0, 0.0});
  const material::SteelParameters steel = elastic_steel();
  const auto bar = [&](int a, int b, double area) {
    model.add_element(std::make_unique<Truss>(std::array<int, 2>{a, b}, model.coordinates(a),
                                              model.coordinates(b), area,
                                              material::SteelUniaxial(steel, 1.0)));
  };
  bar(left, apex, 100.0);
  bar(right, apex, 100.0);
  bar(apex, driver, 5.0 * 1000.0 / 210000.0); // spring k = E A / L = 5 N/mm
  model.fix_all(left);
  model.fix_all(right);
  for (const int node : {apex, driver}) {
    for (const auto dof : {model::ux, model::uz, model::rx, model::ry, model::rz}) {
      model.fix(node, dof);
    }
  }
  StaticAnalysis analysis(model);
  analysis.use_displacement_control(driver, model::uy);
  int jumps = 0;
  for (int step = 1; step <= 120; ++step) {
    const StepReport report = analysis.step_to(-5.0 * step);
    ASSERT_TRUE(report.converged) << "step " << step << ": " << report.failure;
    jumps += report.used_regularised_newton;
  }
  EXPECT_GE(jumps, 1);
  EXPECT_LT(analysis.displacement(apex, model::uy), -100.0); // inverted: below -h
  const EnergyBalance& energy = analysis.energy();
  EXPECT_GT(energy.released_in_jumps, 0.01 * energy.external_work);
  EXPECT_NEAR(energy.dissipated, 0.0, 1e-9 * energy.external_work);
  EXPECT_LT(energy.relative_error(), 1e-4); // trapezoidal work over smooth steps
}

} // namespace
} // namespace brb::analysis
