// The condensed BRB macro element (DESIGN.md section 4): its condensed tangent against
// central differences of its own forces, objectivity (a rotated brace gives the axis-aligned
// response), commit / revert and failure semantics, agreement with the expanded brace model
// (bare core here; the core in its casing in tests/slow), and the brace's placement.
#include "brb/analysis/brb_element.hpp"
#include "brb/material/parameter_error.hpp"

#include "support/brace_fixtures.hpp"
#include "support/brb_element_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace brb::analysis {
namespace {

using element::Matrix3;
using element::NodeConfiguration;
using element::Vector3;

model::BraceSpec small_bare_core() {
  return test::girona_d3_bare_core(4, true); // 4 core elements + 4 end-zone elements
}

struct Evaluation {
  bool ok = false;
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;
  std::string failure;
};

Evaluation evaluate(BRBElement& element, std::span<const NodeConfiguration> nodes) {
  Evaluation result;
  result.ok = element.evaluate(nodes, result.force, result.tangent, result.failure);
  return result;
}

TEST(BRBElementCondensed, TangentMatchesCentralDifferencesOfTheCondensedForces) {
  // Reference: central differences of the element's own forces, each evaluation solving the
  // internal model from the committed state (path retrace off: a warm-started solve lands
  // anywhere within the internal tolerance of the equilibrium, measured 0.04 N of 2e5 N here,
  // noise that differences over h = 1e-4 mm magnify to 2e-4 of the tangent; a solve from the
  // same predictor errs smoothly). This checks the formula of the condensed tangent. Committed
  // state: yielded in tension (2 dy); trial: further tension with lateral motion and end spins
  // (geometric terms), still loading plastically, so +-h stays on one branch.
  const model::BraceSpec spec = small_bare_core();
  NewtonSettings tight;
  tight.relative_force_tolerance = 1e-12;
  tight.position_round_off = 1e-16;
  tight.retrace_target_ratio = 0.0;
  const double length = spec.total_length();
  BRBElement element({0, 1}, Vector3::Zero(), Vector3(length, 0.0, 0.0), spec, std::nullopt, tight);
  const double dy = element.internal_brace().yield_deformation;
  const auto committed = test::outer_configuration(Vector3::Zero(), Matrix3::Identity(), length,
                                                   Vector3(2.0 * dy, 0.0, 0.0), Vector3::Zero());
  ASSERT_TRUE(evaluate(element, committed).ok);
  element.commit();
  ASSERT_GT(element.axial_force(), element.internal_brace().yield_force);

  std::array<NodeConfiguration, 2> base =
      test::outer_configuration(Vector3::Zero(), Matrix3::Identity(), length,
                                Vector3(2.3 * dy, 0.4, -0.3), Vector3(1e-3, -2e-3, 1.5e-3));
  base[0].rotation = element::rotation_from_vector(Vector3(0.5e-3, 1e-3, -0.5e-3));
  const Evaluation at_base = evaluate(element, base);
  ASSERT_TRUE(at_base.ok) << at_base.failure;

  Eigen::MatrixXd numerical(12, 12);
  for (int j = 0; j < 12; ++j) {
    const bool spin = j % 6 >= 3;
    const double h = 1e-4; // mm or rad: the nested solve's round-off limits smaller steps
    std::array<Eigen::VectorXd, 2> forces;
    for (int side = 0; side < 2; ++side) {
      auto nodes = base;
      const double step = side == 0 ? h : -h;
      Vector3 delta = Vector3::Zero();
      delta[j % 3] = step;
      NodeConfiguration& node = nodes[j / 6];
      if (spin)
        node.rotation = element::rotation_from_vector(delta) * node.rotation;
      else
        node.position += delta;
      const Evaluation perturbed = evaluate(element, nodes);
      ASSERT_TRUE(perturbed.ok) << perturbed.failure;
      forces[side] = perturbed.force;
    }
    numerical.col(j) = (forces[0] - forces[1]) / (2.0 * h);
  }
  // compare the translational and the rotational blocks each on its own scale
  const auto block_error = [&](int rows, int cols) {
    Eigen::MatrixXd a(6, 6), b(6, 6);
    for (int i = 0; i < 2; ++i)
      for (int k = 0; k < 2; ++k) {
        a.block<3, 3>(3 * i, 3 * k) = at_base.tangent.block<3, 3>(6 * i + rows, 6 * k + cols);
        b.block<3, 3>(3 * i, 3 * k) = numerical.block<3, 3>(6 * i + rows, 6 * k + cols);
      }
    return (a - b).norm() / b.norm();
  };
  EXPECT_LT(block_error(0, 0), 1e-5);
  EXPECT_LT(block_error(0, 3), 1e-5);
  EXPECT_LT(block_error(3, 0), 1e-5);
  EXPECT_LT(block_error(3, 3), 1e-5);
}

TEST(BRBElementCondensed, RotatedBraceGivesTheAxisAlignedResponse) {
  // Objectivity: the same brace along an arbitrary direction (its section z turned with
  // it), driven through the same motion in its own axes, must give the same axial force and
  // the same forces in its axes (f_rotated = Q f_aligned), to round-off.
  const model::BraceSpec spec = small_bare_core();
  const double length = spec.total_length();
  const Matrix3 turn = element::rotation_from_vector(Vector3(0.3, -0.7, 1.1));
  const Vector3 start(100.0, -50.0, 30.0);
  BRBElement aligned({0, 1}, Vector3::Zero(), Vector3(length, 0.0, 0.0), spec);
  BRBElement rotated({0, 1}, start, start + turn * Vector3(length, 0.0, 0.0), spec,
                     turn * Vector3::UnitZ());
  ASSERT_LT((rotated.placement().axes - turn).norm(), 1e-12);
  const double dy = aligned.internal_brace().yield_deformation;
  // tension past yield, then compression past the buckling load of the bare core (fixed
  // ends: all outer DOF prescribed), with a small end spin
  for (const double multiple : {0.5, 1.5, 3.0, 1.0, -0.5, -1.0, -1.5, 0.0}) {
    const Vector3 motion(multiple * dy, 0.0, 0.0);
    const Vector3 spin(0.0, 1e-4 * multiple, 0.0);
    const auto a =
        test::outer_configuration(Vector3::Zero(), Matrix3::Identity(), length, motion, spin);
    const auto r = test::outer_configuration(start, turn, length, motion, spin);
    const Evaluation ea = evaluate(aligned, a);
    const Evaluation er = evaluate(rotated, r);
    ASSERT_TRUE(ea.ok) << ea.failure;
    ASSERT_TRUE(er.ok) << er.failure;
    aligned.commit();
    rotated.commit();
    const double scale = aligned.internal_brace().yield_force;
    EXPECT_NEAR(rotated.axial_force(), aligned.axial_force(), 1e-8 * scale) << multiple << " dy";
    EXPECT_NEAR(rotated.deformation(), aligned.deformation(), 1e-9 * length);
    for (int block = 0; block < 4; ++block) {
      const Vector3 expected = turn * ea.force.segment<3>(3 * block);
      const double unit = block % 2 == 0 ? scale : scale * length;
      EXPECT_LT((er.force.segment<3>(3 * block) - expected).norm(), 1e-8 * unit);
    }
  }
  EXPECT_NEAR(rotated.energy().dissipated, aligned.energy().dissipated,
              1e-8 * aligned.energy().dissipated);
}

TEST(BRBElementCondensed, RevertKeepsTheCommittedStateAndEvaluationsDoNotAccumulate) {
  // Evaluating a trial state that yields, then reverting, must leave the element as
  // committed: a later evaluation at the committed configuration gives the committed force
  // (elastic), however many trial evaluations came before.
  const model::BraceSpec spec = small_bare_core();
  const double length = spec.total_length();
  BRBElement element({0, 1}, Vector3::Zero(), Vector3(length, 0.0, 0.0), spec);
  const double dy = element.internal_brace().yield_deformation;
  const auto elastic = test::outer_configuration(Vector3::Zero(), Matrix3::Identity(), length,
                                                 Vector3(0.5 * dy, 0.0, 0.0), Vector3::Zero());
  const Evaluation first = evaluate(element, elastic);
  ASSERT_TRUE(first.ok);
  element.commit();
  const double committed_force = element.axial_force();
  const auto plastic = test::outer_configuration(Vector3::Zero(), Matrix3::Identity(), length,
                                                 Vector3(4.0 * dy, 0.0, 0.0), Vector3::Zero());
  for (int k = 0; k < 3; ++k)
    ASSERT_TRUE(evaluate(element, plastic).ok);
  EXPECT_GT(element.energy().dissipated, 0.0);
  element.revert_to_committed();
  EXPECT_EQ(element.energy().dissipated, 0.0);
  const Evaluation again = evaluate(element, elastic);
  ASSERT_TRUE(again.ok);
  EXPECT_NEAR((again.force - first.force).norm(), 0.0, 1e-9 * committed_force)
      << (again.force - first.force).transpose() << "\n"
      << first.force.transpose();
  EXPECT_EQ(element.energy().dissipated, 0.0);
}

TEST(BRBElementCondensed, OuterForcesAreInEquilibriumToRoundOff) {
  // Theory: nothing loads the internal nodes, so the outer forces of an exact internal
  // equilibrium balance (sum of forces 0; sum of moments about the start node 0); what they
  // miss is the sum of the inner residuals. The nested solver polishes its converged states
  // (NewtonSettings::polish_corrections), so that sum is round-off, not the inner tolerance
  // (1e-9 of the largest element force per DOF) summed over the internal nodes. Measured
  // without the polish: force sums of 3e-6 to 1.6e-4 N and a moment sum of 0.21 N mm here
  // (limits 1e-6 N and 2.9e-3 N mm). Trial: yielded in tension with
  // lateral motion and end spins, evaluated first from rest, then again from that committed
  // state at a nearby target (the path retrace's warm start).
  const model::BraceSpec spec = small_bare_core();
  const double length = spec.total_length();
  BRBElement element({0, 1}, Vector3::Zero(), Vector3(length, 0.0, 0.0), spec);
  const double dy = element.internal_brace().yield_deformation;
  const double yield_force = element.internal_brace().yield_force;
  for (const double multiple : {2.0, 2.3, 2.31}) {
    std::array<NodeConfiguration, 2> nodes =
        test::outer_configuration(Vector3::Zero(), Matrix3::Identity(), length,
                                  Vector3(multiple * dy, 0.4, -0.3), Vector3(1e-3, -2e-3, 1.5e-3));
    nodes[0].rotation = element::rotation_from_vector(Vector3(0.5e-3, 1e-3, -0.5e-3));
    const Evaluation trial = evaluate(element, nodes);
    ASSERT_TRUE(trial.ok) << trial.failure;
    const Vector3 start_force = trial.force.segment<3>(0);
    const Vector3 end_force = trial.force.segment<3>(6);
    const Vector3 arm = nodes[1].position - nodes[0].position;
    const Vector3 moment_sum =
        trial.force.segment<3>(3) + trial.force.segment<3>(9) + arm.cross(end_force);
    EXPECT_LT((start_force + end_force).norm(), 1e-11 * yield_force) << multiple << " dy";
    EXPECT_LT(moment_sum.norm(), 1e-11 * yield_force * length) << multiple << " dy";
    element.commit();
  }
}

TEST(BRBElementCondensed, InternalFailureIsReportedAndLeavesTheCommittedStateAlone) {
  // A nested solver allowed no Newton iteration, no cut and no pseudo-time step cannot reach
  // a yielded state: evaluate() must say why and keep the committed state, so that the
  // committed configuration still evaluates to the committed force.
  const model::BraceSpec spec = small_bare_core();
  const double length = spec.total_length();
  NewtonSettings helpless;
  helpless.max_iterations = 0;
  helpless.max_halvings = 0;
  helpless.fallback_iterations = 0;
  BRBElement element({0, 1}, Vector3::Zero(), Vector3(length, 0.0, 0.0), spec, std::nullopt,
                     helpless);
  const auto rest = test::outer_configuration(Vector3::Zero(), Matrix3::Identity(), length,
                                              Vector3::Zero(), Vector3::Zero());
  const Evaluation at_rest = evaluate(element, rest);
  ASSERT_TRUE(at_rest.ok) << at_rest.failure; // nothing to solve
  element.commit();
  const double dy = element.internal_brace().yield_deformation;
  const auto yielded = test::outer_configuration(Vector3::Zero(), Matrix3::Identity(), length,
                                                 Vector3(3.0 * dy, 0.0, 0.0), Vector3::Zero());
  const Evaluation failed = evaluate(element, yielded);
  EXPECT_FALSE(failed.ok);
  EXPECT_NE(failed.failure.find("BRB element (condensed)"), std::string::npos) << failed.failure;
  element.revert_to_committed();
  const Evaluation again = evaluate(element, rest);
  ASSERT_TRUE(again.ok) << again.failure;
  EXPECT_LT(again.force.norm(), 1e-6);
  EXPECT_EQ(element.energy().dissipated, 0.0);
}

TEST(BRBElementCondensed, AgreesWithTheExpandedModelOnABareCoreCyclicTest) {
  // Same equations, solved nested (condensed) or at once (expanded): the forces must agree
  // to the solvers' tolerance (1e-9 relative each), here asked to 1e-6 of the peak force.
  // Tension to 1.5 dy and compression past the bare core's buckling load (about 3 kN).
  const test::Comparison comparison =
      test::compare_condensed_and_expanded(small_bare_core(), {0.5, 1.5});
  ASSERT_GT(comparison.steps, 20u);
  EXPECT_LT(comparison.largest_difference, 1e-6 * comparison.largest_force)
      << comparison.largest_difference << " N of " << comparison.largest_force << " N";
}

TEST(BRBElementExpanded, BraceAddedInAnyOrientationMatchesTheCondensedElement) {
  // add_brace_to_model puts the internal nodes and elements between two nodes of a model
  // along any direction. Driving both outer nodes of that expanded brace (prescribed motion)
  // must give the forces of the condensed element of the axis-aligned brace, turned.
  const model::BraceSpec spec = small_bare_core();
  const double length = spec.total_length();
  const Matrix3 turn = element::rotation_from_vector(Vector3(-0.4, 0.9, 0.2));
  const Vector3 start(-300.0, 200.0, 1000.0);
  model::Model global;
  const int a = global.add_node(start);
  const int b = global.add_node(start + turn * Vector3(length, 0.0, 0.0));
  const model::BraceHandles brace =
      model::add_brace_to_model(global, spec, a, b, turn * Vector3::UnitZ());
  EXPECT_EQ(brace.start_node, a);
  EXPECT_EQ(brace.end_node, b);
  EXPECT_EQ(brace.nodes.front(), a);
  EXPECT_EQ(brace.nodes.back(), b);
  EXPECT_EQ(global.node_count(), static_cast<int>(brace.nodes.size()));
  NewtonSettings tight;
  tight.relative_force_tolerance = 1e-12;
  tight.position_round_off = 1e-16;
  StaticAnalysis expanded(global, tight);
  expanded.use_prescribed_motion({a, b});
  BRBElement condensed({0, 1}, Vector3::Zero(), Vector3(length, 0.0, 0.0), spec, std::nullopt,
                       tight);
  const double dy = condensed.internal_brace().yield_deformation;
  const double scale = condensed.internal_brace().yield_force;
  for (const double multiple : {0.5, 2.0, 0.0, -0.5, -1.0, 0.5}) {
    const Vector3 motion(multiple * dy, 0.1 * multiple, 0.0);
    const Vector3 spin(2e-4 * multiple, 0.0, -1e-4);
    const auto aligned =
        test::outer_configuration(Vector3::Zero(), Matrix3::Identity(), length, motion, spin);
    const auto rotated = test::outer_configuration(start, turn, length, motion, spin);
    const Evaluation reference = evaluate(condensed, aligned);
    ASSERT_TRUE(reference.ok) << reference.failure;
    condensed.commit();
    expanded.set_motion_target(rotated);
    const StepReport report = expanded.step_to(1.0);
    ASSERT_TRUE(report.converged) << report.failure;
    for (int node = 0; node < 2; ++node) {
      const int global_node = node == 0 ? a : b;
      for (int part = 0; part < 2; ++part) {
        const Vector3 expected = turn * reference.force.segment<3>(6 * node + 3 * part);
        const Vector3 got =
            expanded.internal_force().segment<3>(model::kDofPerNode * global_node + 3 * part);
        EXPECT_LT((got - expected).norm(), 1e-6 * (part == 0 ? scale : scale * length))
            << multiple << " dy, node " << node << (part == 0 ? " force" : " moment");
      }
    }
  }
}

TEST(BracePlacement, AxesAreRightHandedWithSectionZAlongTheGivenVectorOrADefault) {
  // Default: section z along global Z made orthogonal to the axis; for a brace along Z,
  // global Y. A section z along the axis, or coincident nodes, is an error.
  const auto check_axes = [](const model::BracePlacement& placement) {
    EXPECT_LT((placement.axes.transpose() * placement.axes - Matrix3::Identity()).norm(), 1e-12);
    EXPECT_NEAR(placement.axes.determinant(), 1.0, 1e-12);
  };
  const auto diagonal = model::BracePlacement::between(Vector3::Zero(), Vector3(3.0, 0.0, 4.0));
  check_axes(diagonal);
  EXPECT_LT((diagonal.axes.col(0) - Vector3(0.6, 0.0, 0.8)).norm(), 1e-12);
  EXPECT_LT((diagonal.axes.col(2) - Vector3(-0.8, 0.0, 0.6)).norm(), 1e-12);
  const auto vertical = model::BracePlacement::between(Vector3::Zero(), Vector3(0.0, 0.0, 5.0));
  check_axes(vertical);
  EXPECT_LT((vertical.axes.col(2) - Vector3::UnitY()).norm(), 1e-12);
  const auto given = model::BracePlacement::between(Vector3::Zero(), Vector3(1.0, 0.0, 0.0),
                                                    Vector3(0.0, 1.0, 1.0));
  check_axes(given);
  EXPECT_LT((given.axes.col(2) - Vector3(0.0, 1.0, 1.0).normalized()).norm(), 1e-12);
  EXPECT_THROW(model::BracePlacement::between(Vector3::Zero(), Vector3(2.0, 0.0, 0.0),
                                              Vector3(1.0, 0.0, 0.0)),
               ParameterError);
  EXPECT_THROW(model::BracePlacement::between(Vector3::Ones(), Vector3::Ones()), ParameterError);
}

TEST(BRBElementExpanded, OuterNodesNotTheBracesLengthApartAreRejected) {
  const model::BraceSpec spec = small_bare_core();
  model::Model global;
  const int a = global.add_node(Vector3::Zero());
  const int b = global.add_node(Vector3(0.9 * spec.total_length(), 0.0, 0.0));
  EXPECT_THROW(model::add_brace_to_model(global, spec, a, b), ParameterError);
  EXPECT_THROW(BRBElement({a, b}, global.coordinates(a), global.coordinates(b), spec),
               ParameterError);
}

} // namespace
} // namespace brb::analysis
