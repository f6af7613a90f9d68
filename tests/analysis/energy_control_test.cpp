// The energy-error control of StaticAnalysis (NewtonSettings::energy_tolerance): steps whose
// trapezoidal work misses the change of stored + dissipated energy (a fiber yielding inside
// the step) are cut until the running balance meets the tolerance.
#include "brb/analysis/static_analysis.hpp"
#include "brb/element/corot_truss.hpp"
#include "brb/material/steel_uniaxial.hpp"

#include "../support/steel_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace brb::analysis {
namespace {

using Truss = element::CorotTruss<material::SteelUniaxial>;

struct TrussRun {
  EnergyBalance balance;
  int substeps = 0;
  int energy_cuts = 0;
};

/// A steel bar (L = 1000 mm, A = 100 mm^2, S275 with mixed linear hardening) in series with
/// an elastic one twice as stiff (so the solver has a free DOF), driven through cycles of
/// +-4 dy of the bar in steps of 0.37 dy: the steps do not land on the yield points, so the
/// trapezoidal rule cuts the corner of the bilinear force path at every yield onset.
TrussRun run_bar(double energy_tolerance) {
  model::Model model;
  const int fixed = model.add_node({0.0, 0.0, 0.0});
  const int middle = model.add_node({1000.0, 0.0, 0.0});
  const int driven = model.add_node({1500.0, 0.0, 0.0});
  const material::SteelParameters steel = test::linear_mixed_steel();
  material::SteelParameters elastic = steel;
  elastic.yield_stress = 1e9;
  model.add_element(std::make_unique<Truss>(std::array<int, 2>{fixed, middle},
                                            model.coordinates(fixed), model.coordinates(middle),
                                            100.0, material::SteelUniaxial(steel, 1000.0)));
  model.add_element(std::make_unique<Truss>(std::array<int, 2>{middle, driven},
                                            model.coordinates(middle), model.coordinates(driven),
                                            100.0, material::SteelUniaxial(elastic, 500.0)));
  model.fix_all(fixed);
  for (const int node : {middle, driven}) {
    for (const auto dof : {model::uy, model::uz, model::rx, model::ry, model::rz})
      model.fix(node, dof);
  }
  NewtonSettings settings;
  settings.energy_tolerance = energy_tolerance;
  StaticAnalysis analysis(model, settings);
  analysis.use_displacement_control(driven, model::ux);
  const double yield_deformation = steel.yield_stress / steel.youngs_modulus * 1500.0;
  const double step = 0.37 * yield_deformation;
  double target = 0.0;
  TrussRun run;
  for (int cycle = 0; cycle < 3; ++cycle) {
    for (const double amplitude : {4.0, -4.0}) {
      const double end = amplitude * yield_deformation;
      while (std::abs(end - target) > 1e-12) {
        target = end > target ? std::min(end, target + step) : std::max(end, target - step);
        const StepReport report = analysis.step_to(target);
        EXPECT_TRUE(report.converged) << report.failure;
        run.substeps += report.substeps;
        run.energy_cuts += report.energy_cuts;
      }
    }
  }
  run.balance = analysis.energy();
  return run;
}

TEST(EnergyControl, WithoutControlTheYieldCornersShowInTheBalance) {
  // Reference (theory): the trapezoidal rule over a step that crosses the yield point misses
  // (E - H) a b A / (2 L) of work (a, b: the elastic and plastic parts of the step), about
  // 1e-3 of the gross work at steps of 0.37 dy; the material's own bookkeeping is exact for
  // linear hardening, so the whole error is the corner.
  const TrussRun run = run_bar(0.0);
  EXPECT_EQ(run.energy_cuts, 0);
  EXPECT_GT(run.balance.relative_error(), 1e-5);
}

TEST(EnergyControl, CutsTheStepsThatCrossYieldUntilTheBalanceMeetsTheTolerance) {
  const TrussRun loose = run_bar(0.0);
  const TrussRun controlled = run_bar(1e-7);
  EXPECT_GT(controlled.energy_cuts, 0);
  EXPECT_LE(controlled.balance.relative_error(), 1e-7);
  // The elastic and fully plastic steps are not cut: the extra substeps are a few per corner
  // (12 corners, halving the crossing step until its corner is small enough).
  EXPECT_LT(controlled.substeps, loose.substeps + 12 * 40);
  // Same physics: the dissipated energy agrees to the accuracy of the loose run.
  EXPECT_NEAR(controlled.balance.dissipated, loose.balance.dissipated,
              loose.balance.relative_error() * loose.balance.gross_work);
}

TEST(EnergyControl, AModelWithoutFreeDofsSteps) {
  // A single bar with its driven end prescribed has nothing to solve for; each step must
  // still go through (it used to fall through every fallback on an empty residual).
  model::Model model;
  const int fixed = model.add_node({0.0, 0.0, 0.0});
  const int driven = model.add_node({1000.0, 0.0, 0.0});
  const material::SteelParameters steel = test::linear_mixed_steel();
  model.add_element(std::make_unique<Truss>(std::array<int, 2>{fixed, driven},
                                            model.coordinates(fixed), model.coordinates(driven),
                                            100.0, material::SteelUniaxial(steel, 1000.0)));
  model.fix_all(fixed);
  for (const auto dof : {model::uy, model::uz, model::rx, model::ry, model::rz})
    model.fix(driven, dof);
  StaticAnalysis analysis(model);
  analysis.use_displacement_control(driven, model::ux);
  const StepReport report = analysis.step_to(0.5);
  ASSERT_TRUE(report.converged) << report.failure;
  EXPECT_EQ(report.substeps, 1);
  // Reference (theory): elastic bar, F = E A delta / L.
  EXPECT_NEAR(analysis.control_force(), 210000.0 * 100.0 * 0.5 / 1000.0, 1e-6);
}

TEST(EnergyControl, RelativeErrorIsMeasuredAgainstTheGrossWork) {
  // Reference (definition): after full elastic cycles the net work is ~0, so the balance is
  // scaled by the sum of |work| per step instead.
  EnergyBalance balance;
  balance.external_work = 1e-3;
  balance.stored = 0.0;
  balance.dissipated = 0.0;
  balance.gross_work = 1000.0;
  EXPECT_DOUBLE_EQ(balance.relative_error(), 1e-6);
}

} // namespace
} // namespace brb::analysis
