#include "brb/ida/ida_study.hpp"

#include "brb/analysis/sdof_exact.hpp"
#include "brb/frame/frame_run.hpp"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace brb::ida {
namespace {

Eigen::Vector3d unit_vector(io::SuiteDirection direction) {
  switch (direction) {
  case io::SuiteDirection::x:
    return Eigen::Vector3d::UnitX();
  case io::SuiteDirection::y:
    return Eigen::Vector3d::UnitY();
  case io::SuiteDirection::z:
    return Eigen::Vector3d::UnitZ();
  }
  return Eigen::Vector3d::UnitX();
}

std::string measure_name(IntensityMeasure measure) {
  return measure == IntensityMeasure::sa_t1 ? "sa_t1" : "pga";
}

} // namespace

nlohmann::json to_json(const HuntFillSettings& trace) {
  return {{"first_intensity", trace.first_intensity},
          {"step", trace.step},
          {"step_growth", trace.step_growth},
          {"resolution", trace.resolution},
          {"max_runs", trace.max_runs},
          {"max_intensity", trace.max_intensity}};
}

std::string content_digest(std::string_view text) {
  std::uint64_t hash = 14695981039346656037ULL; // FNV-1a offset basis and prime (64-bit)
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ULL;
  }
  std::ostringstream hex;
  hex << std::hex << std::setw(16) << std::setfill('0') << hash;
  return hex.str();
}

IdaStudy::IdaStudy(model::FrameSpec spec, std::string model_source, io::GroundMotionSuite suite,
                   IdaSettings settings)
    : spec_(std::move(spec)), model_source_(std::move(model_source)), suite_(std::move(suite)),
      settings_(std::move(settings)) {
  run_options_ = frame::run_options_of(spec_);
  if (settings_.drift_limit)
    run_options_.drift_limit = *settings_.drift_limit;
  // An IDA needs only the peaks: no histories are recorded.
  run_options_.recorders = frame::RecorderRequest{false, false, false, false, {}};
  // One component per run, along the record's own direction (set per run).
  run_options_.directions = {Eigen::Vector3d::UnitX()};

  frame::FrameModel frame = frame::build_frame(spec_, model_source_, settings_.braces);
  for (const frame::StoryReference& story : frame.stories)
    story_names_.push_back(story.name);
  if (settings_.period) {
    period_ = *settings_.period;
  } else {
    const std::vector<double> periods = frame::gravity_periods(frame, run_options_, 1);
    if (periods.empty())
      throw std::runtime_error("the frame has no vibration mode: give the period");
    period_ = periods.front();
  }
  for (std::size_t k = 0; k < suite_.motions.size(); ++k) {
    const io::GroundMotion& motion = suite_.motions[k];
    const double intensity =
        (settings_.measure == IntensityMeasure::sa_t1
             ? analysis::spectral_acceleration(motion, period_, settings_.damping_ratio)
             : motion.peak_acceleration()) /
        io::kStandardGravity;
    if (!(intensity > 0.0))
      throw std::invalid_argument("record \"" + suite_.records[k].name +
                                  "\" has zero intensity: it cannot be scaled");
    record_intensity_.push_back(intensity);
  }
}

double IdaStudy::record_intensity(std::size_t record) const {
  return record_intensity_.at(record);
}

std::string IdaStudy::measure_label() const {
  if (settings_.measure == IntensityMeasure::pga)
    return "PGA";
  std::ostringstream label;
  label << "Sa(T1 = " << std::setprecision(4) << period_ << " s, "
        << 100.0 * settings_.damping_ratio << " %)";
  return label.str();
}

nlohmann::json IdaStudy::header(const std::string& model_text,
                                const std::string& suite_text) const {
  nlohmann::json records = nlohmann::json::array();
  for (std::size_t k = 0; k < suite_.records.size(); ++k) {
    const io::GroundMotion& motion = suite_.motions[k];
    const std::string_view samples(reinterpret_cast<const char*>(motion.acceleration.data()),
                                   motion.acceleration.size() * sizeof(double));
    records.push_back({{"name", suite_.records[k].name},
                       {"dt", motion.dt},
                       {"samples_digest", content_digest(samples)},
                       {"intensity", record_intensity_[k]}});
  }
  return {{"journal", "brb ida"},
          {"version", 1},
          {"model_digest", content_digest(model_text)},
          {"suite_digest", content_digest(suite_text)},
          {"measure", measure_name(settings_.measure)},
          {"period", period_},
          {"damping_ratio", settings_.damping_ratio},
          {"drift_limit", run_options_.drift_limit},
          {"braces", frame::brace_override_name(settings_.braces)},
          {"trace", to_json(settings_.trace)},
          {"records", records}};
}

IdaPoint IdaStudy::run(std::size_t record, double intensity) const {
  const auto started = std::chrono::steady_clock::now();
  IdaPoint point;
  point.record = static_cast<int>(record);
  point.record_name = suite_.records.at(record).name;
  point.intensity = intensity;
  point.scale = intensity / record_intensity_.at(record);
  try {
    frame::FrameModel frame = frame::build_frame(spec_, model_source_, settings_.braces);
    frame::FrameRunOptions options = run_options_;
    const io::GroundMotion& motion = suite_.motions[record];
    analysis::GroundAcceleration component;
    component.direction = unit_vector(suite_.records[record].direction);
    options.directions = {component.direction};
    component.dt = motion.dt;
    component.acceleration = motion.acceleration;
    for (double& value : component.acceleration)
      value *= point.scale;
    if (!(options.dt > 0.0))
      options.dt = motion.dt;
    const frame::FrameRunResult result = frame::run_time_history(frame, {component}, options);
    point.converged = result.gravity_converged && result.converged;
    point.collapse = result.collapsed   ? CollapseKind::drift_limit
                     : !point.converged ? CollapseKind::numerical
                                        : CollapseKind::none;
    point.max_drift = result.max_drift;
    point.residual_drift.reserve(result.residual_drift.size());
    for (const double drift : result.residual_drift)
      point.residual_drift.push_back(std::abs(drift));
    for (const double acceleration : result.peak_floor_acceleration)
      point.peak_floor_acceleration = std::max(point.peak_floor_acceleration, acceleration);
    for (const frame::BraceSummary& brace : result.braces) {
      point.max_core_strain = std::max(point.max_core_strain, brace.max_core_strain);
      point.max_cid = std::max(point.max_cid, brace.cumulative_inelastic_deformation);
    }
    point.end_time = result.end_time;
    point.fallbacks = static_cast<int>(result.fallbacks.size());
    point.stop_reason = result.stop_reason;
  } catch (const std::exception& error) {
    // A solver that throws has failed to find the response: numerical collapse, said so.
    point.converged = false;
    point.collapse = CollapseKind::numerical;
    point.stop_reason = std::string("the analysis failed: ") + error.what();
  }
  point.run_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return point;
}

std::vector<IdaPoint> IdaStudy::trace(std::size_t record, const std::map<double, IdaPoint>& known,
                                      const std::function<void(const IdaPoint&)>& finished) const {
  HuntAndFill tracer(settings_.trace);
  std::vector<IdaPoint> points;
  while (const std::optional<double> intensity = tracer.next_intensity()) {
    const auto found = known.find(*intensity);
    if (found != known.end()) {
      points.push_back(found->second);
    } else {
      points.push_back(run(record, *intensity));
      if (finished)
        finished(points.back());
    }
    tracer.record(*intensity, points.back().collapsed());
  }
  return points;
}

} // namespace brb::ida
