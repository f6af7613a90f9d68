// The solver passes a snap-through under displacement control (a limit point of the
// controlled path) by pseudo-transient continuation, and books the energy it releases.
#include "brb/analysis/static_analysis.hpp"

#include "support/shallow_truss.hpp"

#include <gtest/gtest.h>

namespace brb::analysis {
namespace {

TEST(SnapThrough, SoftSpringOverAShallowTrussSnapsAndReleasesEnergy) {
  // Reference: a shallow two-bar (von Mises) truss, half-span 1000 mm, rise 50 mm, loaded at
  // its apex through a soft spring (5 N/mm) whose far end is driven down. The truss' force
  // on its apex peaks and then falls faster than the spring can follow: the controlled path
  // has a limit point and the apex must jump through to the inverted, stable configuration.
  // Everything is elastic, so the work done equals the stored energy plus what the jump
  // released (the drop of stored energy across the jump, absorbed by the pseudo-viscosity
  // that carries it).
  const auto truss = test::shallow_truss();
  model::Model& model = truss->model;
  const int apex = truss->apex, driver = truss->driver;
  for (const auto dof : {model::ux, model::uz, model::rx, model::ry, model::rz})
    model.fix(driver, dof);
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
