// The IDA workflow on a linear elastic frame, where every answer is known from one linear
// response: the peak drift is proportional to the scale, so each record's IDA curve is a
// straight line through the origin whose slope is (peak drift of the unscaled record) /
// (its intensity), and its collapse intensity is drift_limit / slope (within the bisection
// resolution). Also: determinism across thread counts and the journal round trip.
#include "brb/analysis/sdof_exact.hpp"
#include "brb/frame/frame_builder.hpp"
#include "brb/frame/frame_run.hpp"
#include "brb/ida/ida_run.hpp"
#include "brb/ida/ida_study.hpp"
#include "brb/io/frame_input.hpp"

#include "io/scratch_directory.hpp"
#include "support/linear_frame.hpp"
#include "support/shared_records.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace brb::ida {
namespace {

using testing::ScratchDirectory;

struct LinearStudy {
  ScratchDirectory scratch;
  std::filesystem::path model;
  std::filesystem::path suite;

  LinearStudy() {
    model = scratch.write("frame.json", test::kLinearFrame);
    nlohmann::json records = nlohmann::json::array();
    for (const std::string_view name : test::kTwoRecordNames)
      records.push_back({{"file", (test::shared_ground_motions() / name).string()}});
    suite = scratch.write("suite.json", nlohmann::json{{"records", records}}.dump());
  }

  IdaStudy study(const IdaSettings& settings) const {
    return IdaStudy(io::read_frame(model), model.string(), io::read_suite(suite), settings);
  }
};

IdaSettings linear_settings() {
  IdaSettings settings;
  settings.trace = {0.25, 0.5, 0.25, 0.02, 10, 0.0};
  return settings;
}

TEST(IdaStudy, RecordIntensityIsSaAtTheFramesFirstPeriod) {
  const LinearStudy linear;
  const IdaStudy study = linear.study(linear_settings());
  // T1 independently: the modal analysis of the same frame through the frame layer
  frame::FrameModel frame = frame::build_frame(io::read_frame(linear.model), "frame.json");
  const double period =
      frame::gravity_periods(frame, frame::run_options_of(io::read_frame(linear.model)), 1).front();
  EXPECT_DOUBLE_EQ(study.period(), period);
  for (std::size_t r = 0; r < study.record_count(); ++r) {
    const io::GroundMotion motion =
        io::read_peer_at2(test::shared_ground_motions() / test::kTwoRecordNames[r]);
    EXPECT_DOUBLE_EQ(study.record_intensity(r),
                     analysis::spectral_acceleration(motion, period, 0.05) / io::kStandardGravity);
  }
}

TEST(IdaStudy, LinearFrameCurvesAreStraightLinesWithThePredictedSlope) {
  const LinearStudy linear;
  const IdaStudy study = linear.study(linear_settings());
  for (std::size_t r = 0; r < study.record_count(); ++r) {
    // the linear response to the unscaled record: the predicted slope of the IDA curve
    frame::FrameModel frame = frame::build_frame(io::read_frame(linear.model), "frame.json");
    frame::FrameRunOptions options = frame::run_options_of(io::read_frame(linear.model));
    options.drift_limit = 1.0;
    const io::GroundMotion& motion = study.suite().motions[r];
    analysis::GroundAcceleration ground;
    ground.dt = motion.dt;
    ground.acceleration = motion.acceleration;
    options.dt = motion.dt;
    const frame::FrameRunResult unscaled = frame::run_time_history(frame, {ground}, options);
    ASSERT_TRUE(unscaled.converged);
    const double peak = *std::max_element(unscaled.max_drift.begin(), unscaled.max_drift.end());
    const double slope = peak / study.record_intensity(r);

    const std::vector<IdaPoint> points = study.trace(r, {}, nullptr);
    ASSERT_GE(points.size(), 4u);
    int below_collapse = 0;
    for (const IdaPoint& point : points) {
      if (point.collapsed()) {
        EXPECT_EQ(point.collapse, CollapseKind::drift_limit) << point.stop_reason;
        // collapse only above the intensity at which the line reaches the drift limit
        EXPECT_GT(point.intensity * slope, study.drift_limit() * (1.0 - 1e-6));
        continue;
      }
      ++below_collapse;
      EXPECT_NEAR(point.peak_drift() / point.intensity, slope, 1e-6 * slope)
          << "record " << r << " at IM " << point.intensity;
    }
    EXPECT_GE(below_collapse, 3);
    // the traced collapse intensity brackets drift_limit / slope within the resolution
    std::vector<double> survived, collapsed;
    for (const IdaPoint& point : points)
      (point.collapsed() ? collapsed : survived).push_back(point.intensity);
    ASSERT_FALSE(collapsed.empty());
    const double lowest_collapse = *std::min_element(collapsed.begin(), collapsed.end());
    const double capacity = study.drift_limit() / slope;
    EXPECT_GE(lowest_collapse, capacity * (1.0 - 1e-9));
    EXPECT_LE(lowest_collapse - capacity, study.settings().trace.resolution);
  }
}

TEST(IdaStudy, ThreadCountDoesNotChangeThePoints) {
  const LinearStudy linear;
  const IdaStudy study = linear.study(linear_settings());
  const auto run = [&](int jobs) {
    const std::filesystem::path file = linear.scratch.path() / ("journal" + std::to_string(jobs));
    Journal journal = Journal::create(file, study.header("model", "suite"));
    IdaProgress progress(nullptr, study.record_count(), study.settings().trace.max_runs);
    const std::vector<std::map<double, IdaPoint>> none(study.record_count());
    return run_ida_threads(study, journal, none, jobs, progress);
  };
  const std::vector<IdaPoint> one = run(1), two = run(2);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t k = 0; k < one.size(); ++k) {
    IdaPoint a = one[k], b = two[k];
    a.run_time = b.run_time = 0.0; // the one measured, non-deterministic field
    EXPECT_EQ(to_json(a), to_json(b)) << "point " << k;
  }
}

TEST(IdaStudy, ResumedTraceTakesJournalPointsAndRunsOnlyTheRest) {
  const LinearStudy linear;
  const IdaStudy study = linear.study(linear_settings());
  const std::filesystem::path file = linear.scratch.path() / "journal.jsonl";
  const nlohmann::json header = study.header("model", "suite");
  std::vector<IdaPoint> full;
  {
    Journal journal = Journal::create(file, header);
    full = study.trace(0, {}, [&](const IdaPoint& point) { journal.append(to_json(point)); });
  }
  ASSERT_GE(full.size(), 4u);
  // keep the header and the first three runs, as if the process had been killed then
  std::vector<nlohmann::json> entries;
  Journal::resume(file, header, entries);
  ASSERT_EQ(entries.size(), full.size());
  entries.resize(3);
  const auto known = points_by_record(entries, study.record_count());
  int new_runs = 0;
  const std::vector<IdaPoint> resumed =
      study.trace(0, known[0], [&](const IdaPoint&) { ++new_runs; });
  EXPECT_EQ(new_runs, static_cast<int>(full.size()) - 3);
  ASSERT_EQ(resumed.size(), full.size());
  for (std::size_t k = 0; k < full.size(); ++k) {
    IdaPoint a = full[k], b = resumed[k];
    a.run_time = b.run_time = 0.0;
    EXPECT_EQ(to_json(a), to_json(b));
  }
}

TEST(IdaStudy, PgaMeasureIsThePeakGroundAccelerationInG) {
  const LinearStudy linear;
  IdaSettings settings = linear_settings();
  settings.measure = IntensityMeasure::pga;
  const IdaStudy study = linear.study(settings);
  // El Centro (Peknold version): PGA 0.319 g per SOURCES.md
  EXPECT_NEAR(study.record_intensity(0), 0.319, 0.0005);
  EXPECT_EQ(study.measure_label(), "PGA");
}

TEST(IdaStudy, DigestIsFnv1a64) {
  // FNV-1a 64 test vectors (Fowler, Noll, Vo; IETF draft-eastlake-fnv): "" and "a"
  EXPECT_EQ(content_digest(""), "cbf29ce484222325");
  EXPECT_EQ(content_digest("a"), "af63dc4c8601ec8c");
}

} // namespace
} // namespace brb::ida
