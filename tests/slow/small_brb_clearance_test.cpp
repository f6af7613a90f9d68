// The small BRB of the source's verification cases (BRB_SOURCE_FACTS section 6; the brace file
// of validation/thesis_small_case4: 10 x 10 mm core, 100 mm, in a 30 x 30 mm mortar casing
// without a steel tube) on case 4's protocol (one cycle each at 1, 2, 3, 5, 10 and 15 dy),
// at two clearances. The source gives none; the specimen assumed 0.05 mm until session 31 and
// now assumes 0.3 mm (the 3D references of cases 1 to 4 stay at 0.05 mm, solid_small_case1..4).
// Slow: about 45 s.
//
// Why it matters: the source reports for case 4 "stiffness and strength degradation in
// compression after mortar failure, tension side like case 3". At 0.05 mm the core's buckling
// waves are too shallow to load the casing and nothing of this happens up to 15 dy (in
// brb solid neither). Session 28's sweep (validation/thesis_small_case4's notes): up to 0.2 mm
// the casing takes no damage; from 0.25 mm up its mortar cracks through in bending in the 15
// dy cycle (0.25, 0.3 mm) or the 10 dy cycle (0.35 to 0.5 mm) and the brace buckles as a
// whole, while the tension peaks stay those of 0.05 mm. This test keeps the model able to
// show the source's case 4 at a clearance of 3 % of the core's thickness.
#include "brb/analysis/cyclic_test.hpp"
#include "brb/io/brace_input.hpp"
#include "brb/io/protocol.hpp"
#include "brb/model/brace_model.hpp"
#include "support/specimen_files.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace brb::analysis {
namespace {

struct LastCycle {
  double peak_compression = 0.0; ///< N (negative)
  double at_largest_shortening = 0.0;
  double peak_tension = 0.0;
};

struct ClearanceRun {
  CyclicTestResult result;
  LastCycle last;
};

ClearanceRun run_case_four(double clearance) {
  model::BraceSpec spec = io::read_brace(test::specimen_brace("thesis_small_case4"));
  spec.casing->gap_y = clearance;
  spec.casing->gap_z = clearance;
  model::BraceModel brace = model::build_brace_model(spec);
  // case 4's cycles (its protocol.json) in steps of dy / 2: the validation protocol's dy / 10
  // gives the same cycles (15 dy cycle -52.1 kN, then -33.2 kN at -15 dy, against -51.2 and
  // -33.2 kN here; measured)
  const double dy = brace.yield_deformation;
  const io::LoadingProtocol protocol = io::cyclic_protocol(
      "case 4", {{dy, 1}, {2 * dy, 1}, {3 * dy, 1}, {5 * dy, 1}, {10 * dy, 1}, {15 * dy, 1}},
      0.5 * dy);
  ClearanceRun run;
  run.result =
      run_cyclic_test(brace, protocol.deformation, protocol.cycle, protocol.cycle_amplitude);
  const int last = protocol.cycle.back();
  double extreme = 0.0;
  for (const CyclicStep& step : run.result.steps) {
    if (step.cycle != last)
      continue;
    run.last.peak_compression = std::min(run.last.peak_compression, step.force);
    run.last.peak_tension = std::max(run.last.peak_tension, step.force);
    if (step.deformation < extreme) {
      extreme = step.deformation;
      run.last.at_largest_shortening = step.force;
    }
  }
  std::cout << "[ clearance " << clearance << " mm ] 15 dy cycle: compression peak "
            << run.last.peak_compression << " N, at -15 dy " << run.last.at_largest_shortening
            << " N, tension " << run.last.peak_tension << " N; casing failure "
            << run.result.indicators.casing_failure << ", global buckling "
            << run.result.indicators.global_buckling << "\n";
  return run;
}

TEST(SmallBrbClearance, AtAFewTenthsOfAMillimetreCaseFourDegradesInCompressionOnly) {
  const ClearanceRun tight = run_case_four(0.05);
  const ClearanceRun open = run_case_four(0.3);
  ASSERT_TRUE(tight.result.completed) << tight.result.stop_reason;
  ASSERT_TRUE(open.result.completed) << open.result.stop_reason;

  // 0.05 mm: no casing failure, and the 15 dy cycle's compression keeps its peak to the end
  // (the linear hardening: the force at the largest shortening is the peak)
  EXPECT_FALSE(tight.result.indicators.casing_failure);
  EXPECT_GT(tight.last.at_largest_shortening / tight.last.peak_compression, 0.99);

  // 0.3 mm, the source's case 4: mortar failure (the casing cracks through in bending, residual
  // strength <= 0.1, README "Casing failure"), then the core buckles with the casing and the
  // compression force falls within the 15 dy cycle; the bound 0.9 is the validation check's
  // (thesis_small_case4: at least 10 % below the cycle's peak; measured 0.65)
  EXPECT_TRUE(open.result.indicators.casing_failure);
  EXPECT_TRUE(open.result.indicators.global_buckling);
  EXPECT_LT(open.last.at_largest_shortening / open.last.peak_compression, 0.9);
  // "tension side like (3)": the core straightens in tension and the tension peak is that of
  // the undamaged brace (the same steel path in tension; measured equal to 1e-4)
  EXPECT_NEAR(open.last.peak_tension, tight.last.peak_tension, 0.01 * tight.last.peak_tension);
  // the jumps of the collapse are booked (steps of dy / 2, no balance control: measured
  // 4.6e-5; the validation protocol's dy / 10 with the control gives 5.0e-7)
  EXPECT_LT(open.result.energy_balance.relative_error(), 1e-4);
}

} // namespace
} // namespace brb::analysis
