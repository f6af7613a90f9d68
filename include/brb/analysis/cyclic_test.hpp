// A virtual cyclic test of a brace: displacement control of the axial deformation (change
// of distance between the two outer nodes, elongation positive) through a loading history,
// with the hysteresis, per-cycle metrics and the solver's account of what it did.
#pragma once

#include "brb/analysis/brace_indicators.hpp"
#include "brb/analysis/static_analysis.hpp"
#include "brb/model/brace_model.hpp"

#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace brb::analysis {

struct CyclicStep {
  int step = 0;                          ///< 0 is the unloaded initial state
  int cycle = 0;                         ///< full cycle the point belongs to (0: initial point)
  double deformation = 0.0;              ///< mm, elongation positive
  double force = 0.0;                    ///< N, tension positive
  double max_lateral_displacement = 0.0; ///< mm, largest lateral motion of a node
  int substeps = 1;                      ///< substeps the step needed
};

/// Checkpoints (io/state_archive.hpp).
template <class Archive, class Self>
requires io::state_of<Self, CyclicStep>
void state_fields(Archive& archive, Self& step) {
  archive(step.step, step.cycle, step.deformation, step.force, step.max_lateral_displacement,
          step.substeps);
}

/// Called after every converged step of a cyclic test, e.g. to report progress on a long run.
using StepObserver = std::function<void(const CyclicStep&)>;

/// The element outputs after a step (issue 4 "histories when asked"): the running maxima and
/// flags of BraceIndicators up to that step, with the step's own core strain and energy.
struct ElementHistoryPoint {
  int step = 0;
  /// Mean axial strain of the yielding core: change of the chord between its end nodes over
  /// its length (the truss fidelity: its core strain).
  double core_strain = 0.0;
  double dissipated_energy = 0.0; ///< N mm, by all the brace's elements, with jumps
  BraceIndicators indicators;     ///< up to and including this step
};

template <class Archive, class Self>
requires io::state_of<Self, ElementHistoryPoint>
void state_fields(Archive& archive, Self& point) {
  archive(point.step, point.core_strain, point.dissipated_energy, point.indicators);
}

/// One node of the brace's deformed shape after a step (`brb cyclic --shape-steps`): where
/// the core buckles inside the gap, how the casing follows, where the mortar bears and is
/// crushed. Lateral components are along the brace's section axes y and z.
struct BraceShapeNode {
  int step = 0;
  int node = 0;                ///< index along the brace, 0 at the start node
  double position = 0;         ///< mm along the brace axis from the start node, initial
  double lateral_y = 0;        ///< mm, the node's displacement along section y
  double lateral_z = 0;        ///< mm, along section z
  bool station = false;        ///< a casing station (elsewhere the casing columns below are 0)
  double casing_lateral_y = 0; ///< mm, the casing node's displacement along y
  double casing_lateral_z = 0; ///< mm, along z
  double bearing_force_y = 0;  ///< N, the casing's force on the core along y (mortar
                               ///< bearing and unbonding layer): opposes the core's motion
                               ///< relative to the casing
  double bearing_force_z = 0;  ///< N, along z
  double mortar_damage = 0;    ///< largest bearing damage of the link's faces, 0 to 1
  /// N, the casing's axial force on the core at the station (Coulomb friction, with the
  /// sub-element waves' share): along the brace axis, it opposes the core's slip
  double friction_force = 0;
  double wave_normal_force = 0; ///< N, N_w of the sub-element waves (0 without them)
  /// N, axial force of the core element from this node to the next (at the last node, of the
  /// element ending there); compression negative. 0 for the truss fidelity (no beams).
  double core_axial_force = 0;
  /// -, that element's chord strain (elongation over initial length): where the core's
  /// plastic strain goes (a friction gradient can localise it at the ends). 0 for the truss
  double core_axial_strain = 0;
  /// N, axial force of the casing beam from this station to the next (at the last station, of
  /// the beam ending there); compression negative
  double casing_axial_force = 0;
};

template <class Archive, class Self>
requires io::state_of<Self, BraceShapeNode>
void state_fields(Archive& archive, Self& node) {
  archive(node.step, node.node, node.position, node.lateral_y, node.lateral_z, node.station,
          node.casing_lateral_y, node.casing_lateral_z, node.bearing_force_y, node.bearing_force_z,
          node.mortar_damage, node.friction_force, node.wave_normal_force, node.core_axial_force,
          node.core_axial_strain, node.casing_axial_force);
}

struct CycleMetrics {
  int index = 0;                ///< 1-based
  double amplitude = 0.0;       ///< mm (from the protocol)
  double energy = 0.0;          ///< N mm, loop area (integral of F d delta over the cycle)
  double max_tension = 0.0;     ///< N
  double max_compression = 0.0; ///< N (negative)
};

template <class Archive, class Self>
requires io::state_of<Self, CycleMetrics>
void state_fields(Archive& archive, Self& cycle) {
  archive(cycle.index, cycle.amplitude, cycle.energy, cycle.max_tension, cycle.max_compression);
}

struct CyclicTestResult {
  std::vector<CyclicStep> steps;
  std::vector<CycleMetrics> cycles; ///< cycles that were completed
  bool completed = false;
  std::string stop_reason;   ///< empty when completed
  double energy_total = 0.0; ///< N mm, integral of F d delta over the whole history
  double max_tension = 0.0;
  double max_compression = 0.0;
  EnergyBalance energy_balance; ///< external work vs stored + dissipated (all elements)
  int iterations = 0;
  int substeps = 0;
  int regularised_steps = 0;
  int unstable_accepted = 0;       ///< substeps accepted although their equilibrium was unstable
  int energy_cuts = 0;             ///< substeps cut by the energy-error control
  int far_branch_cuts = 0;         ///< substeps cut by the far-branch control (NewtonSettings)
  int energy_tolerance_missed = 0; ///< substeps accepted at that control's floor
  SolverWork work;                 ///< where the solver's effort went (assemblies, iterations)
  BraceIndicators indicators;
  std::vector<ElementHistoryPoint> history; ///< one per step, when asked for
  /// The deformed shape after each asked step and after the last converged one, when shapes
  /// were asked for (CyclicTest::record_shapes_at), step by step.
  std::vector<BraceShapeNode> shapes;
  /// A run taken up from a checkpoint (CyclicCheckpoint): the steps the earlier run(s) had
  /// converged (0: this run started from the unloaded state) and their wall time (s).
  int resumed_from_step = 0;
  double seconds_before_resume = 0.0;
};

/// What a checkpoint held besides the test's state.
struct ResumedRun {
  int steps = 0;                ///< steps converged before it
  double elapsed_seconds = 0.0; ///< wall time of the run(s) that wrote it
};

/// Checkpoints of a long cyclic test (`brb cyclic --checkpoint`, `brb validate
/// --checkpoint-dir`): the test's whole state is written to `file` (atomically) at most
/// every `interval_seconds` of wall time after a converged step, and a run that finds the
/// file takes up from it; the file is refused unless it was written for the same `run_key`
/// (the caller's account of the input: brace and protocol files and settings) by this
/// program's checkpoint format.
struct CyclicCheckpoint {
  std::filesystem::path file;
  double interval_seconds = 600.0;
  std::string run_key;
  /// Called once a checkpoint was read (e.g. to say so before a long run goes on).
  std::function<void(const ResumedRun&)> taken_up = {};
};

/// Folds converged steps into a CyclicTestResult's hysteresis: the step list, the work of the
/// force (trapezoidal in the deformation), the peak forces and the metrics of each completed
/// cycle (loop energy and peaks). One rule for the fiber brace (CyclicTest) and the 3D
/// continuum model (`brb solid`), so both report cycles the same way.
class HysteresisAccumulator {
public:
  /// `result` must hold the initial point as its first step and outlive the accumulator.
  explicit HysteresisAccumulator(CyclicTestResult& result) : result_(&result) {}

  /// Checkpoints (io/state_archive.hpp): the open cycle (the result is the owner's).
  template <class Archive, class Self>
  requires io::state_of<Self, HysteresisAccumulator>
  friend void state_fields(Archive& archive, Self& accumulator) {
    archive(accumulator.open_cycle_);
  }

  /// Appends `step` after the last one. `cycle_ends`: it is the last point of its cycle (the
  /// cycle then counts as completed); `cycle_amplitude[c-1]`: the amplitude of cycle c.
  void append(const CyclicStep& step, bool cycle_ends, std::span<const double> cycle_amplitude);

private:
  CyclicTestResult* result_;
  CycleMetrics open_cycle_;
};

/// A cyclic test that can be continued: each follow() drives the brace on from where the
/// last one stopped, so a caller can decide the next cycles from the response so far (the
/// AISC 341 K3.4c sequence adds cycles at 1.5 Delta_bm until the cumulative inelastic
/// deformation reaches its target). run_cyclic_test is one follow() over a whole history.
class CyclicTest {
public:
  /// `brace` must outlive the test; its model is driven at its end node along x.
  explicit CyclicTest(model::BraceModel& brace, NewtonSettings settings = {},
                      bool record_history = false);
  CyclicTest(const CyclicTest&) = delete;
  CyclicTest& operator=(const CyclicTest&) = delete;

  /// Drives the brace through `deformation` (mm, the points after the current state, in
  /// order); `cycle[k]` is the full cycle point k belongs to and `cycle_amplitude[c-1]` the
  /// amplitude of cycle c (the whole list so far, cycles numbered over the whole test). A
  /// cycle whose last point is the last of `deformation` counts as completed, so give whole
  /// cycles. Returns false (and says why in result().stop_reason) at the first step the
  /// solver cannot pass; once stopped, further calls do nothing and return false.
  bool follow(std::span<const double> deformation, std::span<const int> cycle,
              std::span<const double> cycle_amplitude);

  /// Records the brace's deformed shape (BraceShapeNode) after each of these steps (step
  /// numbers as in CyclicStep; step 0: the initial state) and, in result(), after the last
  /// converged step. Call before follow().
  void record_shapes_at(std::vector<int> steps);

  /// Calls `observer` after every converged step from now on (none: stop calling).
  void observe_steps(StepObserver observer) { observer_ = std::move(observer); }

  /// The deformed shape after the last converged step, labelled with `step`.
  std::vector<BraceShapeNode> shape(int step) const;

  /// Indicators of the brace up to the last converged step.
  const BraceIndicators& indicators() const { return tracker_.indicators(); }
  /// Steps converged so far (the initial point not counted).
  int steps_done() const { return static_cast<int>(result_.steps.size()) - 1; }

  /// Checkpoints (io/state_archive.hpp): the test after its last converged step (hysteresis,
  /// histories, shapes, indicators, the analysis and every element). load_state reads it into
  /// a test of a brace built from the same input, before its first step; follow() then drives
  /// it on from the step after the checkpoint's (give it the points from there).
  void save_state(io::StateWriter& out) const;
  void load_state(io::StateReader& in);
  /// The result so far (solver statistics and energy balance up to the last step).
  CyclicTestResult result() const;

private:
  double core_strain() const;

  model::BraceModel* brace_;
  StaticAnalysis analysis_;
  BraceIndicatorTracker tracker_;
  bool record_history_ = false;
  std::optional<std::vector<int>> shape_steps_; ///< sorted; set by record_shapes_at
  StepObserver observer_;
  std::optional<std::pair<int, int>> yielding_ends_; ///< for the mean core strain
  CyclicTestResult result_;
  HysteresisAccumulator hysteresis_{result_};
};

/// The stop reason of a cyclic test whose `step` (to `deformation`, mm) failed: "step 12
/// (deformation 3.5 mm): <the solver's failure>".
std::string step_failure(int step, double deformation, const std::string& failure);

/// Sets `result`'s completion (no stop reason), energy balance and solver statistics from the
/// analysis that ran it.
void record_solver_statistics(const StaticAnalysis& analysis, CyclicTestResult& result);

/// Drives `brace` through the deformation history (mm; first point 0), one analysis step per
/// point; `cycle[k]` is the full cycle point k belongs to and `cycle_amplitude[c-1]` the
/// amplitude of cycle c. Stops at the first step the solver cannot pass (after substepping
/// and the fallback algorithm) and says why. `shape_steps`: see CyclicTest::record_shapes_at;
/// `observer`: called after every converged step. `checkpoint`: takes the run up from its
/// file if there is one (read_checkpoint) and writes it while running (CyclicCheckpoint);
/// the caller removes the file once it has written the run's outputs.
CyclicTestResult run_cyclic_test(model::BraceModel& brace, std::span<const double> deformation,
                                 std::span<const int> cycle,
                                 std::span<const double> cycle_amplitude,
                                 NewtonSettings settings = {}, bool record_history = false,
                                 std::optional<std::vector<int>> shape_steps = std::nullopt,
                                 StepObserver observer = {},
                                 const std::optional<CyclicCheckpoint>& checkpoint = std::nullopt);

/// Writes `test`'s state after its last converged step to checkpoint.file (atomically, so a
/// run killed while writing leaves the previous checkpoint), with the run key and the wall
/// time so far.
void write_checkpoint(const CyclicTest& test, const CyclicCheckpoint& checkpoint,
                      double elapsed_seconds);

/// Reads checkpoint.file into `test` (built from the same input, before its first step).
/// Throws io::CheckpointMismatch when the file is not a checkpoint of this program's format,
/// was written for another run key or does not fit the model.
ResumedRun read_checkpoint(CyclicTest& test, const CyclicCheckpoint& checkpoint);

} // namespace brb::analysis
