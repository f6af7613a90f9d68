// The solver passes a snap-through under displacement control (a limit point of the
// controlled path) by pseudo-transient continuation, and books the energy it releases.
#include "brb/analysis/static_analysis.hpp"

#include "support/shallow_truss.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <span>
#include <string>

namespace brb::analysis {
namespace {

/// The shallow truss with its driver free along y alone (driven by displacement control).
std::unique_ptr<test::ShallowTruss> truss_driven_along_y() {
  auto truss = test::shallow_truss();
  for (const auto dof : {model::ux, model::uz, model::rx, model::ry, model::rz})
    truss->model.fix(truss->driver, dof);
  return truss;
}

TEST(SnapThrough, SoftSpringOverAShallowTrussSnapsAndReleasesEnergy) {
  // Reference: a shallow two-bar (von Mises) truss, half-span 1000 mm, rise 50 mm, loaded at
  // its apex through a soft spring (5 N/mm) whose far end is driven down. The truss' force
  // on its apex peaks and then falls faster than the spring can follow: the controlled path
  // has a limit point and the apex must jump through to the inverted, stable configuration.
  // Everything is elastic, so the work done equals the stored energy plus what the jump
  // released (the drop of stored energy across the jump, absorbed by the pseudo-viscosity
  // that carries it).
  const auto truss = truss_driven_along_y();
  model::Model& model = truss->model;
  const int apex = truss->apex, driver = truss->driver;
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

/// A probe: an element without stiffness on one node that counts its evaluations, so the
/// count is the number of times the model was assembled, seen from outside the solver.
class EvaluationCounter final : public element::Element {
public:
  explicit EvaluationCounter(int node, int& evaluations)
      : node_{node}, evaluations_(&evaluations) {}
  std::span<const int> nodes() const override { return node_; }
  bool evaluate(std::span<const element::NodeConfiguration>, Eigen::VectorXd& force,
                Eigen::MatrixXd& tangent, std::string&) override {
    ++*evaluations_;
    force = Eigen::VectorXd::Zero(6);
    tangent = Eigen::MatrixXd::Zero(6, 6);
    return true;
  }
  void commit() override {}
  void revert_to_committed() override {}
  element::ElementEnergy energy() const override { return {}; }
  void copy_state_from(const element::Element&) override {}

private:
  std::array<int, 1> node_;
  int* evaluations_;
};

TEST(SnapThrough, SolverWorkAccountsForEveryIterationAndEveryAssembly) {
  // StaticAnalysis::work(): each Newton iteration is booked once, as converged, failed or
  // pseudo-time (their sum is total_iterations(), exactly); the assemblies are the element
  // evaluations, counted independently here by a probe element. The limit point's plain
  // Newton fails (stagnates) before the pseudo-time steps pass it, so both are non-zero.
  const auto truss = truss_driven_along_y();
  int evaluations = 0;
  truss->model.add_element(std::make_unique<EvaluationCounter>(truss->apex, evaluations));
  StaticAnalysis analysis(truss->model);
  analysis.use_displacement_control(truss->driver, model::uy);
  for (int step = 1; step <= 120; ++step)
    ASSERT_TRUE(analysis.step_to(-5.0 * step).converged) << "step " << step;
  const SolverWork& work = analysis.work();
  EXPECT_GE(analysis.regularised_steps(), 1);
  EXPECT_GE(work.failed_newton_calls, 1);
  EXPECT_GE(work.failed_newton_iterations, work.failed_newton_calls);
  EXPECT_GE(work.pseudo_time_steps, 1);
  EXPECT_EQ(work.converged_newton_iterations + work.failed_newton_iterations +
                work.pseudo_time_iterations,
            analysis.total_iterations());
  EXPECT_EQ(work.assemblies, evaluations);
  // every correction is tried at one line-search point at least, and every Newton call and
  // predictor assembles its start outside the line search
  EXPECT_GE(work.line_search_assemblies, analysis.total_iterations());
  EXPECT_GT(work.assemblies, work.line_search_assemblies);
}

/// What drive_truss_down measured.
struct DrivenTruss {
  int iterations = 0;
  int jumps = 0;
  double apex_deflection = 0.0;
  double released = 0.0;
};

/// Drives the shallow truss's spring down in 120 steps of 5 mm with `settings`: the Newton
/// iterations and jumps of all steps, the apex's final deflection and the energy released.
DrivenTruss drive_truss_down(const NewtonSettings& settings) {
  const auto truss = truss_driven_along_y();
  model::Model& model = truss->model;
  StaticAnalysis analysis(model, settings);
  analysis.use_displacement_control(truss->driver, model::uy);
  DrivenTruss result;
  for (int step = 1; step <= 120; ++step) {
    const StepReport report = analysis.step_to(-5.0 * step);
    EXPECT_TRUE(report.converged) << "step " << step << ": " << report.failure;
    result.iterations += report.iterations;
    result.jumps += report.used_regularised_newton;
  }
  result.apex_deflection = analysis.displacement(truss->apex, model::uy);
  result.released = analysis.energy().released_in_jumps;
  return result;
}

TEST(SnapThrough, StagnationCutOffGivesUpOnThePlateauSoonerAndLandsOnTheSameBranch) {
  // NewtonSettings::stagnation_iterations: at the limit point plain Newton's residual
  // plateaus (no equilibrium near the predictor); the cut-off hands the step to the fallbacks
  // after 15 iterations instead of 30. Reference: the same run without the cut-off. The
  // truss is elastic, so after the jump both runs must reach the same inverted equilibrium
  // (the equilibrium for a given driver position on the inverted branch is unique), and
  // release the same energy in the jump (the drop of stored energy between the two branches).
  NewtonSettings without;
  without.stagnation_iterations = 0;
  const DrivenTruss reference = drive_truss_down(without);
  const DrivenTruss with_cut_off = drive_truss_down(NewtonSettings{});
  EXPECT_GE(reference.jumps, 1);
  EXPECT_GE(with_cut_off.jumps, 1);
  EXPECT_LT(with_cut_off.iterations, reference.iterations);
  EXPECT_NEAR(with_cut_off.apex_deflection, reference.apex_deflection,
              1e-6 * std::abs(reference.apex_deflection));
  EXPECT_NEAR(with_cut_off.released, reference.released, 0.02 * reference.released);
}

/// The first step over the limit point that fails, with no halving and no pseudo-time step
/// allowed (so the step's iterations are those of its one plain Newton call).
StepReport first_failed_step(const NewtonSettings& cut_off) {
  const auto truss = truss_driven_along_y();
  model::Model& model = truss->model;
  NewtonSettings settings = cut_off;
  settings.max_halvings = 0;
  settings.fallback_iterations = 0;
  StaticAnalysis analysis(model, settings);
  analysis.use_displacement_control(truss->driver, model::uy);
  for (int step = 1; step <= 120; ++step) {
    const StepReport report = analysis.step_to(-5.0 * step);
    if (!report.converged)
      return report;
  }
  return {};
}

TEST(SnapThrough, StagnatedNewtonStopsAtTheCutOffIterationInsteadOfTheLast) {
  // At the limit point the residual plateaus above 0.1 of its start: the default cut-off
  // stops the call at iteration 15; without it, the call runs all 30 iterations.
  const StepReport cut = first_failed_step(NewtonSettings{});
  ASSERT_FALSE(cut.converged);
  ASSERT_FALSE(cut.failure.empty()) << "the limit point was passed by plain Newton";
  EXPECT_EQ(cut.iterations, NewtonSettings{}.stagnation_iterations);
  NewtonSettings without;
  without.stagnation_iterations = 0;
  const StepReport full = first_failed_step(without);
  ASSERT_FALSE(full.failure.empty());
  EXPECT_EQ(full.iterations, without.max_iterations);
}

} // namespace
} // namespace brb::analysis
