// A frame with the brace files' 16-element full braces runs through the braces' first
// yielding and compression excursions (issue 9's references). Model: a 1-storey cut of
// brbf3 (its story-1 bay and braces, the whole building's mass on that floor; data/
// brbf3_story1_cut) under the first 1.6 s of El Centro 1940 x 1. Before the condensed brace
// retraced its internal path between global iterations (StaticAnalysis::retrace_last_path),
// this run stuck at t = 1.43 s for over 25 minutes: fresh internal solves of nearby targets
// gave forces that jumped by more than the global tolerance. Reference for the drift: the
// same frame with truss braces (an independent model of the braces, of the same axial
// stiffness and yield force).
#include "brb/frame/frame_builder.hpp"
#include "brb/frame/frame_run.hpp"
#include "brb/io/frame_input.hpp"
#include "brb/io/ground_motion.hpp"

#include "support/shared_records.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace brb::frame {
namespace {

namespace fs = std::filesystem;

struct CutRun {
  FrameRunResult result;
  double peak_drift = 0.0;
};

CutRun run_cut(BraceOverride braces, double duration) {
  const fs::path file =
      fs::path(BRB_SOURCE_DIR) / "tests" / "slow" / "data" / "brbf3_story1_cut" / "model.json";
  const model::FrameSpec spec = io::read_frame(file);
  FrameModel frame = build_frame(spec, file.string(), braces);
  const io::GroundMotion motion = io::read_peer_at2(test::shared_ground_motions() / "elCentro.AT2");
  analysis::GroundAcceleration ground;
  ground.dt = motion.dt;
  const auto samples = static_cast<std::size_t>(duration / motion.dt + 1e-9) + 1;
  ground.acceleration.assign(
      motion.acceleration.begin(),
      motion.acceleration.begin() +
          static_cast<std::ptrdiff_t>(std::min(samples, motion.acceleration.size())));
  FrameRunOptions options = run_options_of(spec);
  options.recorders = {false, false, false, false, {}};
  CutRun run{run_time_history(frame, {ground}, options), 0.0};
  run.peak_drift = *std::max_element(run.result.max_drift.begin(), run.result.max_drift.end());
  return run;
}

TEST(FrameFullBraces, OneStoreyCutOfBrbf3WithSixteenElementBracesRunsThroughYielding) {
  const double duration = 1.6; // past the stall at 1.43 s; the braces yield from 1.2 s on
  const CutRun full = run_cut(BraceOverride::full, duration);
  ASSERT_TRUE(full.result.converged) << full.result.stop_reason;
  EXPECT_NEAR(full.result.end_time, duration, 1e-9);
  // every global fallback is a halving, never the last resorts (modified Newton, Broyden)
  for (const analysis::FallbackRecord& fallback : full.result.fallbacks)
    EXPECT_NE(fallback.what.find("substeps"), std::string::npos) << fallback.what;
  double cid = 0.0;
  for (const BraceSummary& brace : full.result.braces)
    cid = std::max(cid, brace.cumulative_inelastic_deformation);
  EXPECT_GT(cid, 0.5) << "the braces must yield in this window";
  EXPECT_LE(full.result.energy_balance_error, 0.01);

  const CutRun truss = run_cut(BraceOverride::truss, duration);
  ASSERT_TRUE(truss.result.converged) << truss.result.stop_reason;
  // Same axial stiffness and yield force: the peak drifts agree to a few per cent (measured
  // over 2.5 s: 1.063 % full, 1.061 % truss).
  EXPECT_NEAR(full.peak_drift, truss.peak_drift, 0.05 * truss.peak_drift);
  std::cout << "[ measured ] 1-storey brbf3 cut, " << duration << " s: peak drift full "
            << full.peak_drift << ", truss " << truss.peak_drift << "; largest CID " << cid
            << " dy; " << full.result.fallbacks.size() << " fallbacks; energy balance "
            << full.result.energy_balance_error << "\n";
}

} // namespace
} // namespace brb::frame
