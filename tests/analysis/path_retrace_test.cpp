// Path retrace (StaticAnalysis::retrace_last_path), the warm-started re-solve a condensed
// brace uses between the iterations of a global step: it must land where an adaptive solve
// from the same committed state lands (the reference: step_to of a fresh copy of the model),
// replay every substep of the step it retraces, and refuse, moving nothing, whatever it
// cannot retrace (no step, a target too far, another committed state); a substep that
// passed a limit point is retraced onto the branch it jumped to, its energy booked as the
// continuation books it.
#include "brb/analysis/brb_element.hpp"
#include "brb/analysis/static_analysis.hpp"
#include "brb/model/brace_model.hpp"

#include "support/brace_fixtures.hpp"
#include "support/brb_element_fixtures.hpp"
#include "support/shallow_truss.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <vector>

namespace brb::analysis {
namespace {

using element::Matrix3;
using element::NodeConfiguration;
using element::Vector3;

/// The bare Girona D3 core (4 core elements): it yields in tension in a few substeps.
model::BraceSpec bare_core() {
  return test::girona_d3_bare_core(4, true);
}

std::array<NodeConfiguration, 2> target(double length, double axial, double lateral) {
  return test::outer_configuration(Vector3::Zero(), Matrix3::Identity(), length,
                                   Vector3(axial, lateral, -0.5 * lateral),
                                   Vector3(2e-4, -1e-4, 3e-4));
}

/// Forces at the two prescribed nodes (12 components) of a converged state.
Eigen::VectorXd end_forces(const StaticAnalysis& analysis, const model::BraceHandles& brace) {
  Eigen::VectorXd forces(12);
  forces.head<6>() = analysis.internal_force().segment<6>(model::kDofPerNode * brace.start_node);
  forces.tail<6>() = analysis.internal_force().segment<6>(model::kDofPerNode * brace.end_node);
  return forces;
}

/// An adaptive solve of a fresh model from rest to `to`: the reference.
Eigen::VectorXd adaptive_forces(const model::BraceSpec& spec,
                                std::span<const NodeConfiguration> to) {
  model::BraceModel fresh = model::build_brace_model(spec);
  StaticAnalysis analysis(fresh.model);
  analysis.use_prescribed_motion({fresh.start_node, fresh.end_node});
  analysis.set_motion_target(to);
  const StepReport report = analysis.step_to(1.0);
  EXPECT_TRUE(report.converged) << report.failure;
  return end_forces(analysis, fresh);
}

TEST(PathRetrace, RetracesEverySubstepToTheAdaptiveSolutionOfANearbyTarget) {
  const model::BraceSpec spec = bare_core();
  model::BraceModel brace = model::build_brace_model(spec);
  const model::BraceModel twin = model::build_brace_model(spec); // the committed states
  const double length = spec.total_length();
  const double dy = brace.yield_deformation;
  StaticAnalysis analysis(brace.model);
  analysis.use_prescribed_motion({brace.start_node, brace.end_node});
  const AnalysisPathState start = analysis.path_state();

  const auto first = target(length, 2.0 * dy, 0.4);
  analysis.set_motion_target(first);
  StepReport adaptive = analysis.step_to(1.0);
  ASSERT_TRUE(adaptive.converged) << adaptive.failure;
  ASSERT_GT(adaptive.substeps, 1) << "the test needs a step the adaptive solve cuts";

  // Global-Newton-like corrections of the target, each retraced from the committed state.
  // This first yielding step from rest sits near the edge of the energy-error budget (its
  // substeps were cut until it held): a target that asks for more plastic work may exceed it
  // and is refused, where the adaptive solve (which then records the path the next
  // corrections retrace, as BRBElement does) cuts the step further.
  int retraced_count = 0;
  for (const double correction : {0.02, -0.01, 0.005, -0.002, 0.0}) {
    brace.model.copy_element_states_from(twin.model);
    analysis.restore_path_state(start);
    const auto next = target(length, (2.0 + correction) * dy, 0.4 * (1.0 - correction));
    analysis.set_motion_target(next);
    const StepReport retraced = analysis.retrace_last_path();
    const Eigen::VectorXd reference = adaptive_forces(spec, next);
    if (!retraced.converged) {
      EXPECT_NE(retraced.failure.find("energy-error budget"), std::string::npos)
          << retraced.failure;
      EXPECT_GT(correction, 0.0) << "a target asking for less work than the recorded one";
      const int recorded_substeps = adaptive.substeps;
      brace.model.copy_element_states_from(twin.model);
      analysis.restore_path_state(start);
      analysis.set_motion_target(next);
      adaptive = analysis.step_to(1.0);
      ASSERT_TRUE(adaptive.converged) << adaptive.failure;
      EXPECT_GT(adaptive.substeps, recorded_substeps);
      continue;
    }
    ++retraced_count;
    EXPECT_EQ(retraced.substeps, adaptive.substeps);
    // Both solves stop within 1e-9 of the force scale of their equilibria; the substeps'
    // plastic integration is the same, so the forces agree to far below 1e-6 Py.
    EXPECT_LT((end_forces(analysis, brace) - reference).lpNorm<Eigen::Infinity>(),
              1e-6 * brace.yield_force)
        << "correction " << correction << " dy";
  }
  EXPECT_GE(retraced_count, 4);
  EXPECT_EQ(analysis.retraced_steps(), retraced_count);
}

TEST(PathRetrace, RefusesWithoutAStepAFarTargetOrAnotherStateAndMovesNothing) {
  const model::BraceSpec spec = bare_core();
  model::BraceModel brace = model::build_brace_model(spec);
  const model::BraceModel twin = model::build_brace_model(spec);
  const double length = spec.total_length();
  const double dy = brace.yield_deformation;
  StaticAnalysis analysis(brace.model);
  analysis.use_prescribed_motion({brace.start_node, brace.end_node});
  const AnalysisPathState start = analysis.path_state();

  analysis.set_motion_target(target(length, 0.5 * dy, 0.1));
  StepReport refused = analysis.retrace_last_path();
  EXPECT_FALSE(refused.converged);
  EXPECT_NE(refused.failure.find("no converged step"), std::string::npos) << refused.failure;

  const Vector3 rest = analysis.node(brace.end_node).position;
  ASSERT_TRUE(analysis.step_to(1.0).converged);
  const Vector3 reached = analysis.node(brace.end_node).position;

  // From the start again, but to a target 3 times as far: beyond retrace_target_ratio.
  brace.model.copy_element_states_from(twin.model);
  analysis.restore_path_state(start);
  analysis.set_motion_target(target(length, 1.5 * dy, 0.3));
  refused = analysis.retrace_last_path();
  EXPECT_FALSE(refused.converged);
  EXPECT_NE(refused.failure.find("moved"), std::string::npos) << refused.failure;
  EXPECT_EQ(refused.substeps, 0);
  EXPECT_EQ(analysis.node(brace.end_node).position, rest);
  EXPECT_EQ(analysis.energy().external_work, 0.0);

  // Not restored: the committed state is the end of the step, not its start.
  ASSERT_TRUE(analysis.step_to(1.0).converged);
  analysis.set_motion_target(target(length, 1.5 * dy, 0.3));
  refused = analysis.retrace_last_path();
  EXPECT_FALSE(refused.converged);
  EXPECT_NE(refused.failure.find("committed state"), std::string::npos) << refused.failure;
  EXPECT_NE(analysis.node(brace.end_node).position, reached);

  NewtonSettings off;
  off.retrace_target_ratio = 0.0;
  StaticAnalysis without(brace.model, off);
  without.use_prescribed_motion({brace.start_node, brace.end_node});
  refused = without.retrace_last_path();
  EXPECT_NE(refused.failure.find("off"), std::string::npos) << refused.failure;
}

TEST(PathRetrace, CondensedBraceForcesAreSmoothWithinAGlobalStep) {
  // The element's use of it: the first evaluation of a step solves adaptively, the next ones
  // (targets near it, as a global Newton asks) retrace. Along a line of targets the retraced
  // axial force must be smooth: its second differences within ten times the internal
  // solver's noise (1e-9 of a force scale of 2e5 N per evaluation, four evaluations' worth in
  // a second difference: 1e-3 N), far below the global tolerance. An element that always solves
  // adaptively may cut a nearby target's step differently, and the plastic flow integrated
  // over other substeps jumps (measured here: 0.155 N between neighbouring targets); both
  // stay within the substeps' integration error of each other.
  const model::BraceSpec spec = bare_core();
  const double length = spec.total_length();
  NewtonSettings adaptive_only;
  adaptive_only.retrace_target_ratio = 0.0;
  BRBElement retracing({0, 1}, Vector3::Zero(), Vector3(length, 0.0, 0.0), spec);
  BRBElement adaptive({0, 1}, Vector3::Zero(), Vector3(length, 0.0, 0.0), spec, std::nullopt,
                      adaptive_only);
  const double dy = retracing.internal_brace().yield_deformation;
  const double yield_force = retracing.internal_brace().yield_force;
  Eigen::VectorXd force, reference;
  Eigen::MatrixXd tangent, reference_tangent;
  std::string failure;
  double largest_retraced = 0.0, largest_adaptive = 0.0;
  for (const double step_end : {1.5, 3.0, 2.0}) { // loading, further, unloading
    std::vector<double> retraced_forces, adaptive_forces;
    for (int point = 0; point <= 10; ++point) {
      // the step's end first (its adaptive solve), then a line of targets around it
      const double offset = point == 0 ? 0.0 : 0.002 * (point - 6);
      const auto nodes = target(length, (step_end + offset) * dy, 0.2 * step_end);
      ASSERT_TRUE(retracing.evaluate(nodes, force, tangent, failure)) << failure;
      ASSERT_TRUE(adaptive.evaluate(nodes, reference, reference_tangent, failure)) << failure;
      EXPECT_LT((force - reference).lpNorm<Eigen::Infinity>(), 1e-4 * yield_force)
          << step_end << " dy, offset " << offset;
      if (point > 0) {
        retraced_forces.push_back(force[6]);
        adaptive_forces.push_back(reference[6]);
      }
    }
    for (std::size_t k = 1; k + 1 < retraced_forces.size(); ++k) {
      const auto second = [k](const std::vector<double>& f) {
        return std::abs(f[k + 1] - 2.0 * f[k] + f[k - 1]);
      };
      largest_retraced = std::max(largest_retraced, second(retraced_forces));
      largest_adaptive = std::max(largest_adaptive, second(adaptive_forces));
    }
    retracing.commit();
    adaptive.commit();
    EXPECT_NEAR(retracing.axial_force(), adaptive.axial_force(), 1e-4 * yield_force);
  }
  EXPECT_LT(largest_retraced, 1e-7 * yield_force);
  EXPECT_EQ(retracing.internal_retraced_steps(), 30); // the ten line targets of each step
  EXPECT_EQ(adaptive.internal_retraced_steps(), 0);
  std::cout << "[ measured ] largest second difference of the axial force along a line of "
               "targets: retraced "
            << largest_retraced << " N, adaptive " << largest_adaptive << " N (Py " << yield_force
            << " N)\n";
}

using test::shallow_truss;

TEST(PathRetrace, AJumpIsRetracedOntoTheBranchItReachedWithItsEnergyBooked) {
  // Reference: the adaptive solve (pseudo-transient continuation through the limit point)
  // of the same target from the same committed state.
  const auto truss = shallow_truss();
  const auto twin = shallow_truss(); // the committed element states
  StaticAnalysis analysis(truss->model);
  analysis.use_prescribed_motion({truss->driver});
  const auto driver_at = [&](double y) {
    NodeConfiguration node;
    node.position = Vector3(0.0, y, 0.0);
    return std::array<NodeConfiguration, 1>{node};
  };
  // Drive down in 5 mm steps until a step jumps; keep the state before it.
  AnalysisPathState before_jump;
  double jump_target = 0.0;
  for (int step = 1; step <= 120 && jump_target == 0.0; ++step) {
    twin->model.copy_element_states_from(truss->model);
    before_jump = analysis.path_state();
    analysis.set_motion_target(driver_at(1050.0 - 5.0 * step));
    const StepReport report = analysis.step_to(1.0);
    ASSERT_TRUE(report.converged) << report.failure;
    if (report.used_regularised_newton)
      jump_target = 1050.0 - 5.0 * step;
  }
  ASSERT_NE(jump_target, 0.0) << "the truss never snapped";
  const double recorded_release = analysis.energy().released_in_jumps;

  // The recorded target itself first: the retrace must book what the continuation booked.
  // Nearby targets: the adaptive solve may place its substeps elsewhere in the step (where
  // the control stops on the old branch before the jump), which moves the step's work and
  // release by the trapezoidal rule's error over those substeps (measured: 1.5e-3 of the
  // release), not the branch reached.
  // -1.0 and -1.5 (20 and 30 % of the 5 mm step, within retrace_target_ratio) bring the limit
  // point before the substeps that ended on the upper branch last time: the retrace jumps
  // earlier (StaticAnalysis::retrace_early_jump).
  for (const double correction : {0.0, 0.4, -0.3, 0.1, -1.0, -1.5}) {
    // retrace, then the adaptive solve of the same target from the same state
    truss->model.copy_element_states_from(twin->model);
    analysis.restore_path_state(before_jump);
    analysis.set_motion_target(driver_at(jump_target + correction));
    const StepReport retraced = analysis.retrace_last_path();
    ASSERT_TRUE(retraced.converged) << retraced.failure;
    EXPECT_TRUE(retraced.used_regularised_newton);
    EXPECT_LE(retraced.iterations, 2 * 30) << "Newton from the rest point, not a new flow";
    const double apex = analysis.node(truss->apex).position.y();
    const EnergyBalance retraced_energy = analysis.energy();

    StaticAnalysis adaptive(truss->model);
    truss->model.copy_element_states_from(twin->model);
    adaptive.use_prescribed_motion({truss->driver});
    adaptive.restore_path_state(before_jump);
    adaptive.set_motion_target(driver_at(jump_target + correction));
    const StepReport reference = adaptive.step_to(1.0);
    ASSERT_TRUE(reference.converged) << reference.failure;
    ASSERT_TRUE(reference.used_regularised_newton);
    EXPECT_LT(apex, 0.0); // inverted
    EXPECT_NEAR(apex, adaptive.node(truss->apex).position.y(), 1e-6);
    const double release = retraced_energy.released_in_jumps - before_jump.energy.released_in_jumps;
    const double reference_release =
        adaptive.energy().released_in_jumps - before_jump.energy.released_in_jumps;
    EXPECT_GT(release, 0.0);
    const double tolerance = correction == 0.0 ? 1e-9 : 1e-2;
    EXPECT_NEAR(release, reference_release, tolerance * reference_release) << correction;
    EXPECT_NEAR(retraced_energy.external_work, adaptive.energy().external_work,
                tolerance * reference_release)
        << correction;
    EXPECT_LT(retraced_energy.relative_error(), 1e-4);
    if (correction == 0.0) {
      EXPECT_NEAR(retraced_energy.released_in_jumps, recorded_release, 1e-9 * recorded_release);
    }
  }
}

TEST(PathRetrace, ARetraceThatWouldPassALimitPointByNewtonIsRefused) {
  // A step recorded on the truss's upper branch, retraced to a target past the limit point:
  // the upper branch ends there, and Newton from the recorded states (no line search to hold
  // it back) converges onto the inverted branch, releasing stored energy no work supplied.
  // The retrace must refuse it (the adaptive solve then books the jump).
  const auto truss = shallow_truss();
  const auto twin = shallow_truss();
  NewtonSettings patient; // Newton free to get across: no line search, many iterations
  patient.max_iterations = 300;
  patient.line_search = false;
  patient.stagnation_iterations = 0;
  StaticAnalysis analysis(truss->model, patient);
  analysis.use_prescribed_motion({truss->driver});
  const auto driver_at = [&](double y) {
    NodeConfiguration node;
    node.position = Vector3(0.0, y, 0.0);
    return std::array<NodeConfiguration, 1>{node};
  };
  const auto jumps_from = [&](const AnalysisPathState& start, double y) {
    truss->model.copy_element_states_from(twin->model);
    analysis.restore_path_state(start);
    analysis.set_motion_target(driver_at(y));
    const StepReport report = analysis.step_to(1.0);
    EXPECT_TRUE(report.converged) << report.failure;
    return report.used_regularised_newton;
  };
  // Drive down in 20 mm steps until one jumps; bisect that step for the limit point.
  AnalysisPathState start;
  double top = 1050.0;
  for (;;) {
    twin->model.copy_element_states_from(truss->model);
    start = analysis.path_state();
    analysis.set_motion_target(driver_at(top - 20.0));
    const StepReport report = analysis.step_to(1.0);
    ASSERT_TRUE(report.converged) << report.failure;
    if (report.used_regularised_newton)
      break;
    top -= 20.0;
    ASSERT_GT(top, 0.0) << "the truss never snapped";
  }
  double before = top, after = top - 20.0; // no jump at `before`, a jump at `after`
  while (before - after > 0.05) {
    const double middle = 0.5 * (before + after);
    (jumps_from(start, middle) ? after : before) = middle;
  }
  ASSERT_GT(top - before, 1.0) << "the limit point is too close to the step's start";
  ASSERT_FALSE(jumps_from(start, before)); // recorded: the upper branch to `before`
  truss->model.copy_element_states_from(twin->model);
  analysis.restore_path_state(start);
  const double past = before - 0.2 * (top - before); // within retrace_target_ratio
  analysis.set_motion_target(driver_at(past));
  const StepReport retraced = analysis.retrace_last_path();
  EXPECT_FALSE(retraced.converged) << "apex at " << analysis.node(truss->apex).position.y();
  EXPECT_NE(retraced.failure.find("another branch"), std::string::npos) << retraced.failure;
  truss->model.copy_element_states_from(twin->model);
  analysis.restore_path_state(start);
  EXPECT_TRUE(jumps_from(start, past));
  EXPECT_LT(analysis.node(truss->apex).position.y(), 0.0);
}

} // namespace
} // namespace brb::analysis
