// One nonlinear time-history analysis of a frame: gravity (load control, then held), modal
// analysis of the gravity state (periods, and the modes Rayleigh damping is fitted to),
// damping, then the ground motion step by step with the implicit (Newmark / HHT) or the
// explicit solver. Recorders compute only what was asked. The run stops early, and says so,
// when a story drift exceeds the drift limit (collapse) or a step fails after every fallback
// (non-convergence): never a silent wrong answer.
#pragma once

#include "brb/analysis/transient_analysis.hpp"
#include "brb/frame/frame_model.hpp"
#include "brb/model/work_skips.hpp"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace brb::frame {

enum class Integrator { newmark, hht, explicit_central_difference };

struct DampingOptions {
  enum class Kind { none, rayleigh, modal };
  Kind kind = Kind::rayleigh;
  int mode_i = 1; ///< Rayleigh: the two modes (1-based) and their ratios
  int mode_j = 3;
  double ratio_i = 0.02;
  double ratio_j = 0.02;
  bool exclude_braces = true; ///< braces out of the initial-stiffness part
  double modal_ratio = 0.02;  ///< modal damping: the same ratio on the first modal_modes
  int modal_modes = 6;
};

struct RecorderRequest {
  bool drifts = true;
  bool floor_accelerations = true;
  bool base_shear = true;
  bool energy = true;
  std::vector<int> braces; ///< user ids of the braces whose histories are written
};

/// Where a time-history run stands, after each converged step (FrameRunOptions::progress).
struct FrameProgress {
  double time = 0.0;       ///< s, reached
  double duration = 0.0;   ///< s, the whole run (record window and free vibration)
  long step = 0;           ///< steps done
  long steps = 0;          ///< steps planned
  double peak_drift = 0.0; ///< largest |story drift ratio| so far
};

struct FrameRunOptions {
  Integrator integrator = Integrator::newmark;
  double hht_alpha = -0.05;
  double dt = 0.0;             ///< s; 0: the record's dt
  double free_vibration = 0.0; ///< s after the record
  double drift_limit = 0.10;   ///< collapse when a story drift ratio exceeds it
  DampingOptions damping;
  RecorderRequest recorders;
  /// Ground-motion directions, one per component (global unit vectors).
  std::vector<Eigen::Vector3d> directions = {Eigen::Vector3d::UnitX()};
  /// Time every dynamic step (steady clock, the solver's step and the recorders): the
  /// stress suite's time-per-step distribution (FrameRunResult::step_wall_times).
  bool record_step_wall_times = false;
  /// Work skips; the run reads requested_recorders (off: every history is computed, all
  /// braces included, and those not asked are dropped at the end: the benchmark's
  /// reference). The element switches are build_frame's.
  model::WorkSkips skips;
  /// Called after every converged step (runs with full braces take minutes to hours:
  /// `brb frame` reports on stderr from it); empty: nothing called.
  std::function<void(const FrameProgress&)> progress;
};

/// A table of histories: a header and rows (one per recorded step).
struct History {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

struct BraceSummary {
  int id = 0;
  std::string fidelity;
  double max_tension = 0.0;                      ///< N
  double max_compression = 0.0;                  ///< N (positive)
  double max_core_strain = 0.0;                  ///< |core strain| peak
  double cumulative_inelastic_deformation = 0.0; ///< multiples of dy
  bool core_fracture = false;
  bool casing_failure = false;
  bool global_buckling = false;
};

struct FrameRunResult {
  bool gravity_converged = false;
  bool converged = false; ///< every step converged (possibly with fallbacks)
  bool collapsed = false; ///< a story drift exceeded the limit
  std::string stop_reason;
  double end_time = 0.0; ///< s reached
  double duration = 0.0; ///< s asked (record + free vibration)
  int steps = 0;
  std::vector<double> periods;        ///< s, of the gravity state
  double explicit_time_step = 0.0;    ///< s, the explicit solver's stable step (0: implicit)
  double added_mass_fraction = 0.0;   ///< explicit: mass added by selective mass scaling
  std::vector<double> max_drift;      ///< per story, peak |drift ratio|
  std::vector<double> residual_drift; ///< per story, at the end
  std::vector<double> peak_floor_acceleration; ///< per floor, absolute, g
  double peak_base_shear = 0.0;                ///< N
  analysis::TransientEnergy energy;
  double energy_balance_error = 0.0; ///< |error| / input energy
  std::vector<analysis::FallbackRecord> fallbacks;
  std::vector<BraceSummary> braces;
  /// s, per converged dynamic step, when FrameRunOptions::record_step_wall_times asks.
  std::vector<double> step_wall_times;
  std::map<std::string, History> histories; ///< only those asked
};

/// The periods (s) of the first `modes` modes of `frame` in its gravity state (gravity applied
/// as run_time_history applies it): e.g. T1 for an intensity measure. Throws
/// std::runtime_error when the gravity load does not converge. The elements are left in the
/// gravity state: build a fresh frame for a time-history run.
std::vector<double> gravity_periods(FrameModel& frame, const FrameRunOptions& options, int modes);

/// Runs `frame` under the ground motion components (one per options.directions entry).
/// The frame's elements are left in the final state.
FrameRunResult run_time_history(FrameModel& frame,
                                const std::vector<analysis::GroundAcceleration>& components,
                                const FrameRunOptions& options);

} // namespace brb::frame
