#include "brb/analysis/cyclic_test.hpp"
#include "brb/io/atomic_file.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <optional>
#include <sstream>
#include <tuple>
#include <unordered_map>
#include <utility>

namespace brb::analysis {

void HysteresisAccumulator::append(const CyclicStep& step, bool cycle_ends,
                                   std::span<const double> cycle_amplitude) {
  CyclicTestResult& result = *result_;
  const CyclicStep& previous = result.steps.back();
  const double work =
      0.5 * (step.force + previous.force) * (step.deformation - previous.deformation);
  result.energy_total += work;
  result.max_tension = std::max(result.max_tension, step.force);
  result.max_compression = std::min(result.max_compression, step.force);
  if (step.cycle != open_cycle_.index) {
    open_cycle_ = CycleMetrics{};
    open_cycle_.index = step.cycle;
    if (step.cycle >= 1 && static_cast<std::size_t>(step.cycle) <= cycle_amplitude.size())
      open_cycle_.amplitude = cycle_amplitude[step.cycle - 1];
  }
  open_cycle_.energy += work;
  open_cycle_.max_tension = std::max(open_cycle_.max_tension, step.force);
  open_cycle_.max_compression = std::min(open_cycle_.max_compression, step.force);
  if (cycle_ends && step.cycle >= 1)
    result.cycles.push_back(open_cycle_);
  result.steps.push_back(step);
}

CyclicTest::CyclicTest(model::BraceModel& brace, NewtonSettings settings, bool record_history)
    : brace_(&brace), analysis_(brace.model, settings), tracker_(brace, brace.model),
      record_history_(record_history) {
  analysis_.use_displacement_control(brace.end_node, model::ux);
  result_.steps.push_back({0, 0, 0.0, 0.0, 0.0, 0});
  // The yielding core's end nodes, for its mean strain (none for the truss fidelity).
  for (std::size_t e = 0; e < brace.in_yielding_zone.size(); ++e) {
    if (!brace.in_yielding_zone[e])
      continue;
    if (!yielding_ends_)
      yielding_ends_ = {brace.nodes[e], brace.nodes[e + 1]};
    yielding_ends_->second = brace.nodes[e + 1];
  }
  if (record_history_)
    result_.history.push_back({0, 0.0, 0.0, tracker_.indicators()});
}

double CyclicTest::core_strain() const {
  if (brace_->truss != nullptr)
    return brace_->truss->core_strain();
  if (!yielding_ends_)
    return 0.0;
  const double initial = (brace_->model.coordinates(yielding_ends_->second) -
                          brace_->model.coordinates(yielding_ends_->first))
                             .norm();
  const double current = (analysis_.node(yielding_ends_->second).position -
                          analysis_.node(yielding_ends_->first).position)
                             .norm();
  return (current - initial) / initial;
}

bool CyclicTest::follow(std::span<const double> deformation, std::span<const int> cycle,
                        std::span<const double> cycle_amplitude) {
  if (!result_.stop_reason.empty())
    return false;
  const BraceIndicatorTracker::Positions position = [&](int node) -> const element::Vector3& {
    return analysis_.node(node).position;
  };
  for (std::size_t k = 0; k < deformation.size(); ++k) {
    const int step_index = static_cast<int>(result_.steps.size());
    const StepReport report = analysis_.step_to(deformation[k]);
    if (!report.converged) {
      result_.stop_reason = step_failure(step_index, deformation[k], report.failure);
      return false;
    }
    CyclicStep step{step_index,
                    cycle[k],
                    analysis_.control_value(),
                    analysis_.control_force(),
                    tracker_.max_lateral_displacement(position),
                    report.substeps};
    tracker_.observe(position, step.deformation, step.force);
    if (shape_steps_ &&
        std::binary_search(shape_steps_->begin(), shape_steps_->end(), step_index)) {
      const std::vector<BraceShapeNode> nodes = shape(step_index);
      result_.shapes.insert(result_.shapes.end(), nodes.begin(), nodes.end());
    }
    if (record_history_) {
      const EnergyBalance& energy = analysis_.energy();
      result_.history.push_back({step.step, core_strain(),
                                 energy.dissipated + energy.released_by_laws,
                                 tracker_.indicators()});
    }
    const bool cycle_ends = k + 1 == deformation.size() || cycle[k + 1] != step.cycle;
    hysteresis_.append(step, cycle_ends, cycle_amplitude);
    if (observer_)
      observer_(step);
  }
  return true;
}

void CyclicTest::save_state(io::StateWriter& out) const {
  out(io::growing(result_.steps), io::growing(result_.cycles), result_.energy_total,
      result_.max_tension, result_.max_compression, io::growing(result_.history),
      io::growing(result_.shapes), hysteresis_, tracker_);
  analysis_.save_state(out);
}

void CyclicTest::load_state(io::StateReader& in) {
  if (steps_done() != 0)
    throw std::logic_error("CyclicTest::load_state: the test has already run steps");
  in(io::growing(result_.steps), io::growing(result_.cycles), result_.energy_total,
     result_.max_tension, result_.max_compression, io::growing(result_.history),
     io::growing(result_.shapes), hysteresis_, tracker_);
  if (result_.steps.empty())
    in.mismatch("a hysteresis without its initial point");
  analysis_.load_state(in);
}

namespace {
// The checkpoint file: this tag, the format's version, the run key, the wall time so far and
// the test's state. The version changes whenever a state's fields change.
constexpr std::string_view kCheckpointTag = "brb cyclic checkpoint";
constexpr std::uint32_t kCheckpointVersion = 2; // 2: split fiber sections, solver work
} // namespace

void write_checkpoint(const CyclicTest& test, const CyclicCheckpoint& checkpoint,
                      double elapsed_seconds) {
  io::StateWriter out;
  out(std::string(kCheckpointTag), kCheckpointVersion, checkpoint.run_key, elapsed_seconds);
  test.save_state(out);
  io::write_file_atomically(checkpoint.file, out.bytes());
}

ResumedRun read_checkpoint(CyclicTest& test, const CyclicCheckpoint& checkpoint) {
  std::ifstream file(checkpoint.file, std::ios::binary);
  if (!file)
    throw io::CheckpointMismatch(checkpoint.file.string() + ": cannot open the checkpoint");
  std::string bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  io::StateReader in(std::move(bytes), checkpoint.file.string());
  // the tag as the writer wrote it (its length, then its characters), checked before any
  // length is trusted: any other file is "not a checkpoint", not a model of another size
  std::uint64_t tag_length = 0;
  std::string tag(kCheckpointTag.size(), '\0');
  if (in.remaining() >= sizeof tag_length + tag.size()) {
    in(tag_length);
    for (char& character : tag)
      in(character);
  }
  if (tag_length != kCheckpointTag.size() || tag != kCheckpointTag)
    in.mismatch("not a checkpoint of brb cyclic");
  std::string run_key;
  std::uint32_t version = 0;
  ResumedRun resumed;
  in(version);
  if (version != kCheckpointVersion)
    in.mismatch("checkpoint format " + std::to_string(version) + " where this program reads " +
                std::to_string(kCheckpointVersion));
  in(run_key);
  if (run_key != checkpoint.run_key)
    in.mismatch("written for another run (the brace, the protocol or the solver settings "
                "differ): delete it to start again");
  in(resumed.elapsed_seconds);
  test.load_state(in);
  if (!in.at_end())
    in.mismatch("bytes left after the model's state");
  resumed.steps = test.steps_done();
  return resumed;
}

void CyclicTest::record_shapes_at(std::vector<int> steps) {
  std::sort(steps.begin(), steps.end());
  shape_steps_ = std::move(steps);
  if (std::binary_search(shape_steps_->begin(), shape_steps_->end(), 0) && result_.shapes.empty())
    result_.shapes = shape(0);
}

std::vector<BraceShapeNode> CyclicTest::shape(int step) const {
  const model::BraceHandles& brace = *brace_;
  const element::Vector3& axis = brace.axes.col(0);
  const auto lateral = [&](int node) {
    const element::Vector3 motion = analysis_.node(node).position - brace_->model.coordinates(node);
    return std::pair{motion.dot(brace.axes.col(1)), motion.dot(brace.axes.col(2))};
  };
  // the casing station at each core node (model node number -> station index)
  std::unordered_map<int, std::size_t> station_at;
  if (brace.casing)
    for (std::size_t s = 0; s < brace.casing->core_nodes.size(); ++s)
      station_at.emplace(brace.casing->core_nodes[s], s);
  std::vector<BraceShapeNode> nodes;
  nodes.reserve(brace.nodes.size());
  for (std::size_t n = 0; n < brace.nodes.size(); ++n) {
    const int node = brace.nodes[n];
    BraceShapeNode point;
    point.step = step;
    point.node = static_cast<int>(n);
    point.position = axis.dot(brace_->model.coordinates(node) - brace.origin);
    std::tie(point.lateral_y, point.lateral_z) = lateral(node);
    if (!brace.beams.empty()) { // local force and deformation [0]: along the element's chord
      const model::CoreBeam& beam = *brace.beams[std::min(n, brace.beams.size() - 1)];
      point.core_axial_force = beam.local_force()[0];
      point.core_axial_strain = beam.frame().local_deformation()[0] / beam.frame().initial_length();
    }
    if (const auto station = station_at.find(node); station != station_at.end()) {
      const model::CasingModel& casing = *brace.casing;
      const std::size_t s = station->second;
      point.station = true;
      std::tie(point.casing_lateral_y, point.casing_lateral_z) = lateral(casing.nodes[s]);
      const element::CasingContact& link = *casing.contacts[s];
      // link_force() is the link's internal force at the core node; the casing pushes the
      // core the other way (axis: friction; y, z: bearing)
      const element::Vector3 on_core = -link.link_force();
      point.friction_force = on_core[0];
      point.bearing_force_y = on_core[1];
      point.bearing_force_z = on_core[2];
      point.mortar_damage = link.max_mortar_damage();
      point.wave_normal_force = link.wave_normal_force();
      point.casing_axial_force =
          casing.beams[std::min(s, casing.beams.size() - 1)]->local_force()[0];
    }
    nodes.push_back(point);
  }
  return nodes;
}

CyclicTestResult CyclicTest::result() const {
  CyclicTestResult result = result_;
  const int last_step = result.steps.back().step;
  if (shape_steps_ && (result.shapes.empty() || result.shapes.back().step != last_step)) {
    const std::vector<BraceShapeNode> nodes = shape(last_step);
    result.shapes.insert(result.shapes.end(), nodes.begin(), nodes.end());
  }
  record_solver_statistics(analysis_, result);
  result.indicators = tracker_.indicators();
  return result;
}

std::string step_failure(int step, double deformation, const std::string& failure) {
  std::ostringstream reason;
  reason << "step " << step << " (deformation " << std::setprecision(6) << deformation
         << " mm): " << failure;
  return reason.str();
}

void record_solver_statistics(const StaticAnalysis& analysis, CyclicTestResult& result) {
  result.completed = result.stop_reason.empty();
  result.energy_balance = analysis.energy();
  result.iterations = analysis.total_iterations();
  result.substeps = analysis.total_substeps();
  result.regularised_steps = analysis.regularised_steps();
  result.unstable_accepted = analysis.unstable_accepted();
  result.energy_cuts = analysis.energy_cuts();
  result.far_branch_cuts = analysis.far_branch_cuts();
  result.energy_tolerance_missed = analysis.energy_tolerance_missed();
  result.work = analysis.work();
}

CyclicTestResult run_cyclic_test(model::BraceModel& brace, std::span<const double> deformation,
                                 std::span<const int> cycle,
                                 std::span<const double> cycle_amplitude, NewtonSettings settings,
                                 bool record_history, std::optional<std::vector<int>> shape_steps,
                                 StepObserver observer,
                                 const std::optional<CyclicCheckpoint>& checkpoint) {
  CyclicTest test(brace, settings, record_history);
  if (shape_steps)
    test.record_shapes_at(std::move(*shape_steps));
  ResumedRun resumed;
  if (checkpoint && std::filesystem::exists(checkpoint->file)) {
    resumed = read_checkpoint(test, *checkpoint);
    if (checkpoint->taken_up)
      checkpoint->taken_up(resumed);
    if (static_cast<std::size_t>(resumed.steps) >= std::max<std::size_t>(deformation.size(), 1))
      throw io::CheckpointMismatch(
          checkpoint->file.string() + ": " + std::to_string(resumed.steps) +
          " steps done where the protocol has " + std::to_string(deformation.size()) + " points");
  }
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return resumed.elapsed_seconds +
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  double last_write = resumed.elapsed_seconds;
  test.observe_steps([&](const CyclicStep& step) {
    if (observer)
      observer(step);
    if (checkpoint && elapsed() - last_write >= checkpoint->interval_seconds) {
      last_write = elapsed();
      write_checkpoint(test, *checkpoint, last_write);
    }
  });
  const auto first = static_cast<std::size_t>(resumed.steps) + 1;
  if (deformation.size() > first)
    test.follow(deformation.subspan(first), std::span<const int>(cycle).subspan(first),
                cycle_amplitude);
  CyclicTestResult result = test.result();
  if (!cycle.empty())
    result.steps.front().cycle = cycle[0];
  result.resumed_from_step = resumed.steps;
  result.seconds_before_resume = resumed.elapsed_seconds;
  return result;
}

} // namespace brb::analysis
