// Issue 5 acceptance on the example buildings (frames/): the inelastic 3-storey BRBF under
// each shared record balances its energy to 1 % of the input (the balance terms are
// independent integrals: ground input, kinetic, viscous, element stored and dissipated
// energies, transient_analysis.hpp); the 9-storey BRBF under each record scaled up until a
// story drift exceeds 10 % completes every run without a crash or NaN and reports the
// collapse (or a non-convergence) as such.
#include "brb/frame/frame_builder.hpp"
#include "brb/frame/frame_run.hpp"
#include "brb/io/csv.hpp"
#include "brb/io/frame_input.hpp"
#include "brb/io/ground_motion.hpp"

#include "support/shared_records.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iostream>

namespace brb::frame {
namespace {

namespace fs = std::filesystem;

struct Building {
  model::FrameSpec spec;
  std::string file;
};

Building example(const std::string& name) {
  const fs::path file = fs::path(BRB_SOURCE_DIR) / "frames" / name / "model.json";
  return {io::read_frame(file), file.string()};
}

FrameRunOptions options_of(const model::FrameSpec& spec) {
  FrameRunOptions options = run_options_of(spec);
  options.recorders = {false, false, false, false, {}};
  return options;
}

analysis::GroundAcceleration component(const io::GroundMotion& motion) {
  analysis::GroundAcceleration ground;
  ground.dt = motion.dt;
  ground.acceleration = motion.acceleration;
  return ground;
}

TEST(FrameRecords, ThreeStoreyFrameBalancesItsEnergyUnderEverySharedRecord) {
  const Building building = example("brbf3");
  for (const fs::path& record : test::shared_at2_records()) {
    FrameModel frame = build_frame(building.spec, building.file);
    const io::GroundMotion motion = io::read_peer_at2(record);
    const FrameRunResult result =
        run_time_history(frame, {component(motion)}, options_of(building.spec));
    ASSERT_TRUE(result.converged) << record.filename() << ": " << result.stop_reason;
    EXPECT_FALSE(result.collapsed) << record.filename();
    // inelastic: the braces dissipate a good part of the input
    EXPECT_GT(result.energy.dissipated, 0.05 * result.energy.input) << record.filename();
    EXPECT_LE(result.energy_balance_error, 0.01) << record.filename();
    std::cout << "[ measured ] " << record.filename().string() << ": peak drift "
              << *std::max_element(result.max_drift.begin(), result.max_drift.end())
              << ", dissipated " << result.energy.dissipated / result.energy.input
              << " of the input, balance error " << result.energy_balance_error << "\n";
  }
}

/// Roof drift history (roof displacement over the building height) from the drift recorder.
std::vector<double> roof_drift(const FrameModel& frame, const FrameRunResult& result) {
  const History& drifts = result.histories.at("drifts");
  double height = 0.0;
  for (const StoryReference& story : frame.stories)
    height += story.height;
  std::vector<double> roof;
  for (const std::vector<double>& row : drifts.rows) {
    double displacement = 0.0;
    for (std::size_t s = 0; s < frame.stories.size(); ++s)
      displacement += row[1 + s] * frame.stories[s].height;
    roof.push_back(displacement / height);
  }
  return roof;
}

TEST(FrameRecords, ExplicitAndImplicitRoofDriftsAgree) {
  // The first 10 s of a moderate (El Centro) and a strong, inelastic (Pacoima Dam) record:
  // Newmark at the model's 0.005 s against central differences at their stable substep
  // (with selective mass scaling of the massless DOF, at most 5 % of the mass).
  const Building building = example("brbf3");
  for (const std::string name : {"elCentro.AT2", "RSN77_SFERN_PUL164.AT2"}) {
    io::GroundMotion motion = io::read_peer_at2(test::shared_ground_motions() / name);
    motion.acceleration.resize(static_cast<std::size_t>(std::lround(10.0 / motion.dt)) + 1);
    std::vector<std::vector<double>> roofs;
    for (const Integrator integrator :
         {Integrator::newmark, Integrator::explicit_central_difference}) {
      FrameModel frame = build_frame(building.spec, building.file);
      FrameRunOptions options = options_of(building.spec);
      options.integrator = integrator;
      options.recorders.drifts = true;
      const FrameRunResult result = run_time_history(frame, {component(motion)}, options);
      ASSERT_TRUE(result.converged) << name << ": " << result.stop_reason;
      EXPECT_LE(result.energy_balance_error, 0.01) << name;
      if (integrator == Integrator::explicit_central_difference) {
        EXPECT_LE(result.added_mass_fraction, 0.05);
      }
      roofs.push_back(roof_drift(frame, result));
    }
    ASSERT_EQ(roofs[0].size(), roofs[1].size());
    double difference = 0.0, reference = 0.0, peak = 0.0;
    for (std::size_t k = 0; k < roofs[0].size(); ++k) {
      difference += std::pow(roofs[1][k] - roofs[0][k], 2);
      reference += std::pow(roofs[0][k], 2);
      peak = std::max(peak, std::abs(roofs[0][k]));
    }
    const double nrms = std::sqrt(difference / reference);
    EXPECT_LE(nrms, 0.02) << name;
    std::cout << "[ measured ] " << name << ": peak roof drift " << peak
              << ", explicit vs implicit NRMS " << nrms << "\n";
  }
}

TEST(FrameRecords, NineStoreyFrameReportsCollapseUnderEveryScaledRecord) {
  const Building building = example("brbf9");
  for (const fs::path& record : test::shared_at2_records()) {
    const io::GroundMotion motion = io::read_peer_at2(record);
    bool collapse_reached = false;
    double scale = 1.0;
    for (int attempt = 0; attempt < 8 && !collapse_reached; ++attempt, scale *= 2.0) {
      FrameModel frame = build_frame(building.spec, building.file);
      io::GroundMotion scaled = motion;
      for (double& value : scaled.acceleration)
        value *= scale;
      const FrameRunResult result =
          run_time_history(frame, {component(scaled)}, options_of(building.spec));
      ASSERT_TRUE(result.gravity_converged);
      for (const double drift : result.max_drift)
        ASSERT_TRUE(std::isfinite(drift)) << record.filename() << " x " << scale;
      ASSERT_TRUE(std::isfinite(result.energy.input));
      const double peak = *std::max_element(result.max_drift.begin(), result.max_drift.end());
      if (result.collapsed) {
        // stopped at the first step beyond the limit, and said so
        EXPECT_GT(peak, building.spec.analysis.drift_limit);
        EXPECT_NE(result.stop_reason.find("collapse"), std::string::npos);
        EXPECT_LT(result.end_time, result.duration);
        collapse_reached = true;
      } else if (!result.converged) {
        // a numerical collapse is reported as such, never as a drift value
        EXPECT_NE(result.stop_reason.find("did not converge"), std::string::npos);
        collapse_reached = true;
      } else {
        EXPECT_LE(peak, building.spec.analysis.drift_limit);
        EXPECT_NEAR(result.end_time, result.duration, 1e-9);
      }
      std::cout << "[ measured ] " << record.filename().string() << " x " << scale
                << ": peak drift " << peak << ", " << result.stop_reason << "\n";
    }
    EXPECT_TRUE(collapse_reached) << record.filename() << ": no collapse up to x " << scale;
  }
}

TEST(FrameRecords, NineStoreyFrameWithSixteenElementBracesPassesTheStoryNineStall) {
  // brbf9 with full braces at the brace files' 16 core elements, dt 0.01 s, under the first
  // 1.8 s of El Centro. Before the projected-residual line search (StaticAnalysis::newton,
  // analysis/line_search.hpp) this run hung at t = 1.70 s: the story-9 brace's Newton stalled
  // in every substep (its contact and friction kinks at the scale of 3e-4 mm defeat
  // backtracking on the residual norm) and each substep went to pseudo-transient
  // continuation, at every outer iteration. Reference: the committed run of the same frame
  // with 4-element braces (bench/pareto/reference/brbf9_full4, an independent computation
  // with a coarser core mesh): in this window the peak story drifts agree within 0.4 %
  // (measured), asked within 2 %.
  const Building building = example("brbf9");
  FrameModel frame = build_frame(building.spec, building.file, BraceOverride::full);
  io::GroundMotion motion = io::read_peer_at2(test::shared_ground_motions() / "elCentro.AT2");
  const double window = 1.8;
  motion.acceleration.resize(static_cast<std::size_t>(std::floor(window / motion.dt + 1e-9)) + 1);
  FrameRunOptions options = options_of(building.spec);
  options.dt = 0.01;
  const FrameRunResult result = run_time_history(frame, {component(motion)}, options);
  ASSERT_TRUE(result.converged) << result.stop_reason;
  EXPECT_FALSE(result.collapsed);
  const fs::path reference =
      fs::path(BRB_SOURCE_DIR) / "bench" / "pareto" / "reference" / "brbf9_full4" / "drifts.csv";
  const std::vector<double> time = io::read_numeric_column(reference, "time").values;
  ASSERT_EQ(result.max_drift.size(), 9U);
  for (std::size_t story = 0; story < result.max_drift.size(); ++story) {
    const std::vector<double> drift =
        io::read_numeric_column(reference, "drift_x_" + std::to_string(story + 1)).values;
    double peak = 0.0;
    for (std::size_t k = 0; k < time.size() && time[k] <= window + 1e-9; ++k)
      peak = std::max(peak, std::abs(drift[k]));
    EXPECT_NEAR(result.max_drift[story], peak, 0.02 * peak) << "story " << story + 1;
    std::cout << "[ measured ] story " << story + 1 << ": peak drift " << result.max_drift[story]
              << " (16 elements) against " << peak << " (4 elements)\n";
  }
}

} // namespace
} // namespace brb::frame
