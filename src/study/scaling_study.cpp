#include "brb/study/scaling_study.hpp"

#include "brb/frame/frame_run.hpp"
#include "brb/io/atomic_file.hpp"
#include "brb/io/frame_input.hpp"
#include "brb/io/ground_motion.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <variant>

namespace brb::study {

namespace {

constexpr int kBottomId = 1;
constexpr int kTopId = 100001;
constexpr int kColumnId = 1;
constexpr int kBeamId = 10001;
constexpr int kBraceId = 20001;

bool is_support(const model::FrameSpec& spec, int node) {
  return std::any_of(spec.supports.begin(), spec.supports.end(),
                     [node](const model::SupportSpec& support) { return support.node == node; });
}

/// The elastic beam of `base` between nodes at `a` and `b` (either order), if any.
const model::ElasticBeamSpec* elastic_member(const model::FrameSpec& base,
                                             const element::Vector3& a, const element::Vector3& b) {
  for (const model::FrameElementSpec& element : base.elements) {
    const auto* beam = std::get_if<model::ElasticBeamSpec>(&element.kind);
    if (beam == nullptr)
      continue;
    const element::Vector3& i = base.node(element.nodes[0]).coordinates;
    const element::Vector3& j = base.node(element.nodes[1]).coordinates;
    if (((i - a).norm() < 1e-6 && (j - b).norm() < 1e-6) ||
        ((i - b).norm() < 1e-6 && (j - a).norm() < 1e-6))
      return beam;
  }
  return nullptr;
}

/// The first elastic beam of `base` with both nodes at height z (a floor beam).
const model::ElasticBeamSpec* floor_beam(const model::FrameSpec& base, double z) {
  for (const model::FrameElementSpec& element : base.elements) {
    const auto* beam = std::get_if<model::ElasticBeamSpec>(&element.kind);
    if (beam != nullptr && std::abs(base.node(element.nodes[0]).coordinates.z() - z) < 1e-6 &&
        std::abs(base.node(element.nodes[1]).coordinates.z() - z) < 1e-6)
      return beam;
  }
  return nullptr;
}

analysis::GroundAcceleration first_seconds(const io::GroundMotion& motion, double seconds) {
  analysis::GroundAcceleration ground;
  ground.dt = motion.dt;
  const auto samples =
      std::min<std::size_t>(motion.acceleration.size(),
                            static_cast<std::size_t>(std::floor(seconds / motion.dt + 1e-9)) + 1);
  ground.acceleration.assign(motion.acceleration.begin(),
                             motion.acceleration.begin() + static_cast<std::ptrdiff_t>(samples));
  return ground;
}

ScalingPoint measure(const model::FrameSpec& base, const ScalingStudyOptions& options,
                     const io::GroundMotion& motion, int braces, double length,
                     const std::string& series) {
  const model::FrameSpec spec = generated_frame(base, braces);
  const analysis::GroundAcceleration ground = first_seconds(motion, length);
  frame::FrameRunOptions run_options = frame::run_options_of(spec);
  run_options.recorders = {true, false, false, false, {}};
  ScalingPoint point;
  point.series = series;
  point.braces = braces;
  point.record_length = length;
  std::vector<double> times;
  for (int repeat = 0; repeat < options.repeats; ++repeat) {
    const double start = process_cpu_seconds();
    frame::FrameModel frame = frame::build_frame(spec, "generated frame", options.braces);
    const frame::FrameRunResult result = frame::run_time_history(frame, {ground}, run_options);
    times.push_back(process_cpu_seconds() - start);
    if (!result.converged)
      throw std::runtime_error("bench scaling: the run of " + std::to_string(braces) +
                               " braces stopped: " + result.stop_reason);
    point.steps = result.steps;
    point.equations = frame.model->dof_count();
    point.peak_drift = *std::max_element(result.max_drift.begin(), result.max_drift.end());
  }
  point.seconds = median(times);
  return point;
}

PowerLawFit fit_series(const std::vector<ScalingPoint>& points, bool by_braces) {
  std::vector<double> sizes, costs;
  for (const ScalingPoint& point : points) {
    sizes.push_back(by_braces ? point.braces : point.record_length);
    costs.push_back(point.seconds);
  }
  return fit_power_law(sizes, costs);
}

std::string fixed(double value, int decimals) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(decimals) << value;
  return text.str();
}

} // namespace

model::FrameSpec generated_frame(const model::FrameSpec& base, int braces) {
  if (braces < 1)
    throw std::invalid_argument("generated_frame: at least one brace");
  const model::FrameElementSpec* first_brace = nullptr;
  for (const model::FrameElementSpec& element : base.elements) {
    if (std::holds_alternative<model::BraceElementSpec>(element.kind) &&
        is_support(base, element.nodes[0])) {
      first_brace = &element;
      break;
    }
  }
  if (first_brace == nullptr)
    throw std::invalid_argument("generated_frame: the frame has no brb element from a support");
  const element::Vector3 bottom = base.node(first_brace->nodes[0]).coordinates;
  const element::Vector3 top = base.node(first_brace->nodes[1]).coordinates;
  const double width = std::abs(top.x() - bottom.x());
  const double height = top.z() - bottom.z();
  if (!(width > 0.0 && height > 0.0))
    throw std::invalid_argument("generated_frame: the first brace must rise diagonally in x-z");
  const element::Vector3 column_top(bottom.x(), bottom.y(), top.z());
  const model::ElasticBeamSpec* column = elastic_member(base, bottom, column_top);
  const model::ElasticBeamSpec* beam = floor_beam(base, top.z());
  if (column == nullptr || beam == nullptr)
    throw std::invalid_argument("generated_frame: no column above the brace's support or no "
                                "floor beam at the brace's top");
  model::NodalMass mass{};
  for (const model::NodalMassSpec& entry : base.masses) {
    if (std::abs(base.node(entry.node).coordinates.z() - top.z()) < 1e-6) {
      mass = entry.mass;
      break;
    }
  }
  const auto support =
      std::find_if(base.supports.begin(), base.supports.end(),
                   [&](const model::SupportSpec& s) { return s.node == first_brace->nodes[0]; });

  model::FrameSpec spec;
  spec.title = "generated: one storey, " + std::to_string(braces) + " braced bays";
  spec.dimension = base.dimension;
  spec.sections = base.sections;
  spec.materials = base.materials;
  for (int i = 0; i <= braces; ++i) {
    const double x = bottom.x() + i * width;
    spec.nodes.push_back({kBottomId + i, element::Vector3(x, bottom.y(), bottom.z())});
    spec.nodes.push_back({kTopId + i, element::Vector3(x, bottom.y(), top.z())});
    model::SupportSpec fixity = *support;
    fixity.node = kBottomId + i;
    spec.supports.push_back(fixity);
    spec.masses.push_back({kTopId + i, mass});
    spec.elements.push_back({kColumnId + i, {kBottomId + i, kTopId + i}, *column});
  }
  const auto& brace = std::get<model::BraceElementSpec>(first_brace->kind);
  for (int i = 0; i < braces; ++i) {
    spec.elements.push_back({kBeamId + i, {kTopId + i, kTopId + i + 1}, *beam});
    // alternate directions: / in even bays, \ in odd ones
    const std::array<int, 2> nodes = i % 2 == 0 ? std::array<int, 2>{kBottomId + i, kTopId + i + 1}
                                                : std::array<int, 2>{kBottomId + i + 1, kTopId + i};
    spec.elements.push_back({kBraceId + i, nodes, brace});
  }
  model::GravitySpec gravity;
  gravity.from_masses = true;
  gravity.steps = base.gravity ? base.gravity->steps : 10;
  spec.gravity = gravity;
  spec.damping = base.damping;
  spec.analysis = base.analysis;
  spec.ground_directions = {model::GroundDirection::x};
  spec.stories.push_back({"1", kBottomId, kTopId});
  spec.floors.push_back({"1", kTopId});
  spec.recorders.drifts = true;
  return spec;
}

ScalingStudyResult run_scaling_study(const ScalingStudyOptions& options) {
  if (options.repeats < 1)
    throw std::invalid_argument("bench scaling: repeats must be >= 1");
  const model::FrameSpec base = io::read_frame(options.frame_file);
  io::GroundMotionOptions motion_options;
  motion_options.scale = options.record_scale;
  const io::GroundMotion motion = io::load_ground_motion(options.record, motion_options);
  ScalingStudyResult result;
  for (const int braces : options.brace_counts) {
    result.brace_series.push_back(
        measure(base, options, motion, braces, options.brace_series_length, "braces"));
  }
  for (const double length : options.record_lengths) {
    result.length_series.push_back(
        measure(base, options, motion, options.length_series_braces, length, "record_length"));
  }
  result.brace_fit = fit_series(result.brace_series, true);
  result.length_fit = fit_series(result.length_series, false);
  return result;
}

void write_scaling_report(const std::filesystem::path& directory,
                          const ScalingStudyOptions& options, const ScalingStudyResult& result) {
  std::ostringstream csv;
  csv << "series,braces,record_length_s,steps,equations,cpu_s,peak_drift\n" << std::setprecision(9);
  for (const auto* series : {&result.brace_series, &result.length_series}) {
    for (const ScalingPoint& point : *series) {
      csv << point.series << "," << point.braces << "," << point.record_length << "," << point.steps
          << "," << point.equations << "," << point.seconds << "," << point.peak_drift << "\n";
    }
  }
  io::write_file_atomically(directory / "scaling.csv", csv.str());

  std::ostringstream md;
  md << "# Cost scaling: number of braces and record length\n\n"
     << "Generated by `brb bench scaling`. Frames: one storey of N braced bays (one brace per "
        "bay, alternating directions) built from the first storey of `"
     << options.frame_file.parent_path().filename().string() << "/"
     << options.frame_file.filename().string()
     << "` (its column and beam sections, its first-storey brace, the mass of its first floor "
        "node on every floor node, its damping and time step); braces as `"
     << frame::brace_override_name(options.braces) << "`. Record: `"
     << options.record.filename().string() << "` (x" << options.record_scale
     << "), its first L seconds. Cost: process CPU seconds of building and running the frame "
        "(gravity, modal analysis, time history), median of "
     << options.repeats << " runs. Fit: log(time) = a + b log(n) by least squares.\n\n"
     << "| series | braces | record (s) | steps | DOF | CPU (s) | CPU per step (ms) | peak drift "
        "|\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const auto* series : {&result.brace_series, &result.length_series}) {
    for (const ScalingPoint& point : *series) {
      md << "| " << point.series << " | " << point.braces << " | " << point.record_length << " | "
         << point.steps << " | " << point.equations << " | " << fixed(point.seconds, 4) << " | "
         << fixed(1e3 * point.seconds / std::max(point.steps, 1), 4) << " | "
         << fixed(100.0 * point.peak_drift, 3) << " % |\n";
    }
  }
  const auto verdict = [](double exponent) {
    return exponent <= 1.1 ? "at most linear (b <= 1.1)" : "FASTER than linear (b > 1.1)";
  };
  md << "\n| cost against | exponent b | R^2 | verdict |\n|---|---|---|---|\n"
     << "| number of braces (record " << options.brace_series_length << " s) | "
     << fixed(result.brace_fit.exponent, 3) << " | " << fixed(result.brace_fit.r_squared, 4)
     << " | " << verdict(result.brace_fit.exponent) << " |\n"
     << "| record length (" << options.length_series_braces << " braces) | "
     << fixed(result.length_fit.exponent, 3) << " | " << fixed(result.length_fit.r_squared, 4)
     << " | " << verdict(result.length_fit.exponent) << " |\n";
  md << "\nThe cost includes a fixed part (building the frame, gravity, the modal analysis) that "
        "weighs most on the smallest frames and shortest records, so an exponent below 1 is "
        "expected there. Against record length, the cost per step also depends on what the "
        "record does: a window that takes in the strong motion needs more Newton iterations per "
        "step (the CPU per step column), which is the physics, not the model's size.\n";
  io::write_file_atomically(directory / "SCALING.md", md.str());
}

} // namespace brb::study
