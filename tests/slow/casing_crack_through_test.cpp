// The small BRB of the source's verification cases (BRB_SOURCE_FACTS section 6; the brace file
// of validation/solid_small_case1, the 3D comparisons' brace: 10 x 10 mm core, 100 mm, in a
// 30 x 30 mm mortar casing without a steel tube, 0.05 mm clearance; thesis_small_case1's
// until session 31, which now assumes 0.3 mm) shortened far beyond case 1's protocol, to -6 mm
// (-46 dy). Slow: about 10 s.
//
// Why it matters: near -43 dy the mortar casing's beams next to the stopper crack through in
// bending. There a softening section cannot carry the axial force of its neighbours, the
// local beam's equal-force solve has no solution, and before the uniform-strain fallback
// (corot_beam_3d.hpp) the element failed and the run stopped at -5.63 mm (session 23, the
// pseudo-transient continuation not coming to rest). With it, the run goes on and shows what
// the source describes for case 1: mortar failure lets the core buckle and the compression
// force falls.
#include "brb/analysis/cyclic_test.hpp"
#include "brb/io/brace_input.hpp"
#include "brb/model/brace_model.hpp"
#include "support/monotonic_shortening.hpp"
#include "support/specimen_files.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>

namespace brb::analysis {
namespace {

TEST(CasingCrackThrough, TheSmallBracesMortarCasingCracksThroughAndTheCoreBuckles) {
  const model::BraceSpec spec = io::read_brace(test::specimen_brace("solid_small_case1"));
  model::BraceModel brace = model::build_brace_model(spec);
  const double dy = brace.yield_deformation;
  // monotonic shortening to -6 mm in steps of dy / 2 (the validation protocol's dy / 10 takes
  // longer and cracks the casing at about the same place: between -5.618 and -5.631 mm,
  // against between -5.609 and -5.674 mm here)
  const double target = -6.0;
  const int steps = static_cast<int>(std::ceil(-target / (0.5 * dy)));
  const CyclicTestResult result = test::run_monotonic(brace, target, steps);
  std::cout << "[ crack ] peak compression " << result.max_compression << " N, at -6 mm "
            << result.steps.back().force << " N; lateral "
            << result.indicators.max_casing_lateral_displacement << " mm; beams on uniform strain "
            << result.indicators.uniform_axial_strain_beams << "; balance "
            << result.energy_balance.relative_error() << "\n";

  ASSERT_TRUE(result.completed) << result.stop_reason;
  // the fallback was needed: some beam could not find an equal-force state
  EXPECT_GT(result.indicators.uniform_axial_strain_beams, 0);
  // the casing cracked through and the brace buckled as a whole (README flag rules)
  EXPECT_TRUE(result.indicators.casing_failure);
  EXPECT_TRUE(result.indicators.global_buckling);
  // Reference: before the crack the core hardens linearly (H_K = 20000 MPa) beyond Py = 27.5
  // kN, so the peak is several times Py; after it the force falls. Measured: -127.6 kN, then
  // -20.1 kN at -6 mm (0.16 of the peak: the buckled brace's mechanism, not zero as the
  // source's 3D model shows). The bound 0.25 tells a force drop from a hardening brace.
  EXPECT_LT(result.max_compression, -4.0 * brace.yield_force);
  EXPECT_LT(std::abs(result.steps.back().force), 0.25 * std::abs(result.max_compression));
  // the jumps' energy is booked: the balance holds as in every validation run
  EXPECT_LT(result.energy_balance.relative_error(), 1e-6);
}

} // namespace
} // namespace brb::analysis
