// Work skips in a frame (DESIGN.md section 10): a window of the 3-storey BRBF (frames/brbf3)
// under Pacoima Dam 1971 with every brace as the full condensed BRB element (2 core elements
// each, so that the test is fast). The exact skips (open links, elastic fast path,
// requested-only recorders) change no recorded number by a single bit: each returns the very
// products of the general path (reference: the same run with the skip off). The reused tangent
// is not bit-exact (a re-solve of the internal brace would start from another internal state);
// its difference is bounded by the internal solver's tolerance.
#include "brb/frame/frame_builder.hpp"
#include "brb/frame/frame_run.hpp"
#include "brb/io/frame_input.hpp"
#include "brb/io/ground_motion.hpp"

#include "support/shared_records.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <variant>

namespace {

using namespace brb;

constexpr double kWindow = 0.03; // s of record: 6 steps of 0.005 s

struct FrameRun {
  frame::FrameRunResult result;
  long reused = 0;
  long open = 0;
  int truss_braces = 0;
};

FrameRun run_brbf3(const model::WorkSkips& skips, frame::BraceOverride braces) {
  const std::filesystem::path file = BRB_SOURCE_DIR "/frames/brbf3/model.json";
  model::FrameSpec spec = io::read_frame(file);
  for (model::FrameElementSpec& element : spec.elements) {
    if (auto* brace = std::get_if<model::BraceElementSpec>(&element.kind))
      brace->brace.core_elements = 2;
  }
  const io::GroundMotion motion =
      io::read_peer_at2(test::shared_ground_motions() / "RSN77_SFERN_PUL164.AT2");
  analysis::GroundAcceleration ground;
  ground.dt = motion.dt;
  const auto samples = static_cast<std::ptrdiff_t>(std::lround(kWindow / motion.dt)) + 1;
  ground.acceleration.assign(motion.acceleration.begin(), motion.acceleration.begin() + samples);
  frame::FrameRunOptions options = frame::run_options_of(spec);
  options.recorders = {true, false, true, false, {2101, 2302}}; // a subset of the histories
  options.skips = skips;
  frame::FrameModel frame = frame::build_frame(spec, file.string(), braces, skips);
  FrameRun run;
  run.result = frame::run_time_history(frame, {ground}, options);
  EXPECT_TRUE(run.result.converged) << run.result.stop_reason;
  for (const frame::BraceReference& brace : frame.braces) {
    run.truss_braces += brace.truss != nullptr;
    if (brace.full) {
      run.reused += brace.full->reused_evaluations();
      for (const element::CasingContact* contact : brace.full->internal_brace().casing->contacts)
        run.open += contact->open_evaluations();
    }
  }
  return run;
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}

/// Largest |a - b| over the largest |b| over every history the runs recorded; -1 when they do
/// not have the same histories of the same shape.
double relative_difference(const frame::FrameRunResult& a, const frame::FrameRunResult& b,
                           bool& identical) {
  identical = true;
  if (a.histories.size() != b.histories.size())
    return -1.0;
  double largest = 0.0, difference = 0.0;
  for (const auto& [name, history] : b.histories) {
    const auto found = a.histories.find(name);
    if (found == a.histories.end() || found->second.columns != history.columns ||
        found->second.rows.size() != history.rows.size())
      return -1.0;
    for (std::size_t r = 0; r < history.rows.size(); ++r) {
      const auto& row_a = found->second.rows[r];
      const auto& row_b = history.rows[r];
      if (row_a.size() != row_b.size())
        return -1.0;
      for (std::size_t c = 1; c < row_b.size(); ++c) { // column 0 is the time
        identical = identical && same_bits(row_a[c], row_b[c]);
        largest = std::max(largest, std::abs(row_b[c]));
        difference = std::max(difference, std::abs(row_a[c] - row_b[c]));
      }
    }
  }
  for (std::size_t s = 0; s < b.max_drift.size(); ++s)
    identical = identical && same_bits(a.max_drift[s], b.max_drift[s]);
  return difference / largest;
}

class FrameSkips : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    all_on_ = new FrameRun(run_brbf3({}, frame::BraceOverride::full));
  }
  static void TearDownTestSuite() {
    delete all_on_;
    all_on_ = nullptr;
  }
  static FrameRun* all_on_;
};

FrameRun* FrameSkips::all_on_ = nullptr;

TEST_F(FrameSkips, AllOnRunRecordsWhatWasAsked) {
  const frame::FrameRunResult& result = all_on_->result;
  EXPECT_EQ(result.steps, 6);
  EXPECT_EQ(result.histories.size(), 3u); // drifts, base_shear, braces
  EXPECT_EQ(result.histories.count("drifts"), 1u);
  EXPECT_EQ(result.histories.count("floor_accelerations"), 0u);
  EXPECT_EQ(result.histories.at("braces").rows.size(), 2u * 7u); // 2 braces x 7 instants
  EXPECT_GT(all_on_->open, 0);                                   // open links were skipped
  EXPECT_GT(all_on_->reused, 0); // and tangents reused (the predictor of every step)
}

TEST_F(FrameSkips, ExactSkipsChangeNoBit) {
  model::WorkSkips open_off, fast_off, recorders_off;
  open_off.open_links = false;
  fast_off.elastic_fast_path = false;
  recorders_off.requested_recorders = false;
  for (const model::WorkSkips& skips : {open_off, fast_off, recorders_off}) {
    const FrameRun run = run_brbf3(skips, frame::BraceOverride::full);
    bool identical = false;
    const double difference = relative_difference(run.result, all_on_->result, identical);
    EXPECT_EQ(difference, 0.0);
    EXPECT_TRUE(identical);
    if (!skips.open_links) {
      EXPECT_EQ(run.open, 0);
    }
  }
}

// Reused tangents: the predictor of each step takes the last evaluation instead of a re-solve
// of the internal brace from its committed (converged) state. In this short window (braces
// elastic, 2 core elements) both land on the same internal equilibrium, so they differ by what
// the internal Newton leaves (NewtonSettings::relative_force_tolerance = 1e-9 of the largest
// element force) carried through the global Newton; 1e-6 of the largest recorded value bounds
// it with room (measured 2e-10). Longer windows with cores in contact can land on neighbouring
// equilibria: `brb bench skips` measures 3e-5 on 0.5 s with 8 core elements (bench/SKIPS.md).
TEST_F(FrameSkips, ReusedTangentsStayWithinTheInternalSolverTolerance) {
  model::WorkSkips reuse_off;
  reuse_off.reuse_tangents = false;
  const FrameRun run = run_brbf3(reuse_off, frame::BraceOverride::full);
  EXPECT_EQ(run.reused, 0);
  bool identical = false;
  const double difference = relative_difference(all_on_->result, run.result, identical);
  ASSERT_GE(difference, 0.0);
  EXPECT_LT(difference, 1e-6);
  std::cout << "reused tangents: relative difference " << difference << "\n";
}

// `auto` resolves the brbf3 braces to trusses (README "The auto fidelity"); off, they run full.
TEST_F(FrameSkips, AutoOffRunsEveryBraceFull) {
  model::WorkSkips auto_off;
  auto_off.auto_fidelity = false;
  const FrameRun off = run_brbf3(auto_off, frame::BraceOverride::automatic);
  EXPECT_EQ(off.truss_braces, 0);
  bool identical = false;
  // the same skips as the all-on run, every brace full: the same run
  EXPECT_EQ(relative_difference(off.result, all_on_->result, identical), 0.0);
  const FrameRun on = run_brbf3({}, frame::BraceOverride::automatic);
  EXPECT_EQ(on.truss_braces, 6);
  const double error = relative_difference(on.result, off.result, identical);
  std::cout << "auto (truss) against full: relative difference " << error << "\n";
  EXPECT_GT(error, 0.0); // a different model
}

} // namespace
