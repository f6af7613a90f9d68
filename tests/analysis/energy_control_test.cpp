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

  /// Steps the analysis to `target` and counts its substeps and cuts.
  void step(StaticAnalysis& analysis, double target) {
    const StepReport report = analysis.step_to(target);
    EXPECT_TRUE(report.converged) << report.failure;
    substeps += report.substeps;
    energy_cuts += report.energy_cuts;
  }
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
        run.step(analysis, target);
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
  EXPECT_GT(run.balance.law_relative_error(), 1e-5);
  // The stresses' trapezoidal work sees the same corners as the external work (the bar's
  // kinematics are linear along its axis): with the misfit set apart the balance holds to
  // the equilibrium tolerance, and the misfit is the laws' error.
  EXPECT_LT(run.balance.relative_error(), 1e-9);
  EXPECT_NEAR(run.balance.relative_misfit(), run.balance.law_relative_error(), 1e-9);
}

TEST(EnergyControl, CutsTheStepsThatCrossYieldUntilTheBalanceMeetsTheTolerance) {
  const TrussRun loose = run_bar(0.0);
  const TrussRun controlled = run_bar(1e-7);
  EXPECT_GT(controlled.energy_cuts, 0);
  EXPECT_LE(controlled.balance.law_relative_error(), 1e-7);
  // The elastic and fully plastic steps are not cut: the extra substeps are a few per corner
  // (12 corners, halving the crossing step until its corner is small enough).
  EXPECT_LT(controlled.substeps, loose.substeps + 12 * 40);
  // Same physics: the dissipated energy agrees to the accuracy of the loose run.
  EXPECT_NEAR(controlled.balance.dissipated, loose.balance.dissipated,
              loose.balance.law_relative_error() * loose.balance.gross_work);
}

/// A shallow two-bar (von Mises) truss of elastic bars, its apex 60 mm above supports
/// 1000 mm away on each side, free to move only along y (driven there).
struct ShallowTruss {
  model::Model model;
  int apex = 0;
};

ShallowTruss shallow_truss() {
  ShallowTruss truss;
  model::Model& model = truss.model;
  const int left = model.add_node({0.0, 0.0, 0.0});
  const int apex = model.add_node({1000.0, 60.0, 0.0});
  const int right = model.add_node({2000.0, 0.0, 0.0});
  material::SteelParameters elastic = test::linear_mixed_steel();
  elastic.yield_stress = 1e9;
  for (const int support : {left, right}) {
    model.add_element(std::make_unique<Truss>(std::array<int, 2>{support, apex},
                                              model.coordinates(support), model.coordinates(apex),
                                              100.0, material::SteelUniaxial(elastic, 1000.0)));
    model.fix_all(support);
  }
  for (const auto dof : {model::uz, model::rx, model::ry, model::rz})
    model.fix(apex, dof);
  truss.apex = apex;
  return truss;
}

/// The shallow truss's apex pushed down through the flat position in steps of 8 mm: the
/// bars' stress work is exact (a linear law), but the apex force is a cubic of its
/// displacement, which the trapezoidal rule does not sum exactly; the balance of the
/// solution shows it and the balance control cuts it.
TrussRun run_shallow_truss(double balance_tolerance) {
  ShallowTruss truss = shallow_truss();
  NewtonSettings settings;
  settings.energy_tolerance = 0.0; // the laws' control off: only the balance control cuts
  settings.balance_tolerance = balance_tolerance;
  StaticAnalysis analysis(truss.model, settings);
  analysis.use_displacement_control(truss.apex, model::uy);
  TrussRun run;
  for (int step = 1; step <= 20; ++step)
    run.step(analysis, -8.0 * step);
  run.balance = analysis.energy();
  return run;
}

TEST(EnergyControl, TheBalanceControlCutsWhatTheKinematicsAddAndLeavesTheLawsAlone) {
  // Reference (theory): elastic bars store E A (L - L0)^2 / (2 L0) each; their stress work
  // over a step is exact (stress linear in strain), so the misfit is 0 and the balance error
  // is the trapezoidal rule's error on the cubic apex force.
  const TrussRun loose = run_shallow_truss(0.0);
  EXPECT_EQ(loose.energy_cuts, 0);
  EXPECT_LT(loose.balance.relative_misfit(), 1e-12);
  EXPECT_GT(loose.balance.relative_error(), 1e-4);
  const TrussRun controlled = run_shallow_truss(1e-6);
  EXPECT_GT(controlled.energy_cuts, 0);
  EXPECT_LE(controlled.balance.relative_error(), 1e-6);
  // the same end state: the stored energy is a function of the apex position alone
  EXPECT_NEAR(controlled.balance.stored, loose.balance.stored, 1e-9 * loose.balance.stored);
}

TEST(EnergyControl, AnErrorTheCutsCouldNotMendIsCarriedNotRepaidByLaterSteps) {
  // Steps of 20 mm through the shallow truss's snap, allowed only two cuts each, commit a
  // balance error beyond the budget (as a jump passed by pseudo-transient continuation
  // does). Short steps after them err by far less than their share of the budget
  // (trapezoidal error f'' h^2 / (12 f), about 1e-6 of their work at h = 0.1 mm), so they
  // must not be cut: cutting them cannot repay the debt and used to take every one of them
  // down to the energy_halvings floor.
  constexpr double tolerance = 1e-5;
  ShallowTruss truss = shallow_truss();
  NewtonSettings settings;
  settings.energy_tolerance = 0.0;
  settings.balance_tolerance = tolerance;
  settings.energy_halvings = 2;
  StaticAnalysis analysis(truss.model, settings);
  analysis.use_displacement_control(truss.apex, model::uy);
  TrussRun snap;
  for (int step = 1; step <= 4; ++step)
    snap.step(analysis, -20.0 * step);
  const EnergyBalance after_snap = analysis.energy();
  ASSERT_GT(after_snap.relative_error(), 2.0 * tolerance); // the debt this test is about
  const auto signed_error = [](const EnergyBalance& balance) {
    return balance.external_work - balance.stored - balance.dissipated -
           balance.integration_misfit - balance.released_in_jumps;
  };

  TrussRun short_steps;
  for (int step = 1; step <= 20; ++step)
    short_steps.step(analysis, -80.0 - 0.1 * step);
  EXPECT_EQ(short_steps.energy_cuts, 0);
  EXPECT_EQ(short_steps.substeps, 20);
  // and the short steps kept to their share: the running error moved by at most the
  // tolerance times their gross work
  const EnergyBalance end = analysis.energy();
  EXPECT_LE(std::abs(signed_error(end) - signed_error(after_snap)),
            tolerance * (end.gross_work - after_snap.gross_work));
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
  EXPECT_DOUBLE_EQ(balance.law_relative_error(), 1e-6);
  // the integration misfit is a term of the balance, not of the laws' balance
  balance.integration_misfit = 1e-3;
  EXPECT_DOUBLE_EQ(balance.relative_error(), 0.0);
  EXPECT_DOUBLE_EQ(balance.law_relative_error(), 1e-6);
  EXPECT_DOUBLE_EQ(balance.relative_misfit(), 1e-6);
}

} // namespace
} // namespace brb::analysis
