// The tangent StaticAnalysis holds after a converged step is the tangent of the state it
// converged to. Newton's iterates are line-search trial points, whose forces alone decide
// them; the element tangents are gathered into the sparse matrix only for the trial that is
// accepted (StaticAnalysis::assemble_forces, gather_tangent), so a missing gather would leave
// the matrix of an earlier iterate (the predictor's). Reference: the same state assembled
// afresh (free_tangent, which reverts to the committed state and assembles it); the shallow
// truss's elastic bars evaluate a configuration the same way every time, so the two
// condensed tangents must be equal to the last bit.
#include "brb/analysis/static_analysis.hpp"

#include "support/shallow_truss.hpp"

#include <gtest/gtest.h>

#include <array>

namespace brb::analysis {
namespace {

using element::NodeConfiguration;
using element::Vector3;

TEST(StaticTangent, ConvergedStepHoldsTheTangentOfItsOwnStateNotOfAnEarlierIterate) {
  const auto truss = test::shallow_truss();
  StaticAnalysis analysis(truss->model);
  analysis.use_prescribed_motion({truss->driver});
  const auto driver_at = [](double y) {
    NodeConfiguration node;
    node.position = Vector3(0.0, y, 0.0);
    return std::array<NodeConfiguration, 1>{node};
  };
  Eigen::MatrixXd previous;
  int steps_with_iterations = 0;
  // Down in 5 mm steps, well before the truss's limit point (measured: the 45th such step,
  // 225 mm of driver travel, is the first to snap): each step converges by Newton on the
  // curved (co-rotational) path.
  for (int step = 1; step <= 8; ++step) {
    analysis.set_motion_target(driver_at(1050.0 - 5.0 * step));
    const StepReport report = analysis.step_to(1.0);
    ASSERT_TRUE(report.converged) << report.failure;
    ASSERT_FALSE(report.used_regularised_newton);
    if (report.iterations > 0)
      ++steps_with_iterations;
    const Eigen::MatrixXd held = analysis.condensed_tangent();
    analysis.free_tangent(); // the committed state assembled again
    const Eigen::MatrixXd fresh = analysis.condensed_tangent();
    ASSERT_EQ(held.rows(), 6);
    EXPECT_EQ(held, fresh) << "step " << step << ": held\n" << held << "\nfresh\n" << fresh;
    // The check has teeth: the tangent moves from step to step, so an earlier one would not
    // pass for this one.
    if (previous.size() > 0)
      EXPECT_GT((held - previous).norm(), 1e-9 * held.norm()) << "step " << step;
    previous = held;
  }
  EXPECT_GT(steps_with_iterations, 0);
  EXPECT_GT(analysis.work().line_search_assemblies, 0);
}

} // namespace
} // namespace brb::analysis
