// Error metrics of the run-time-against-error study (issue 9): what a setting's run gave,
// compared with the case's reference run (the finest `full` setting).
//
// Components (a cyclic test), per cycle the reference completed:
//   cycle_energy: max over the significant cycles of |E_i - E_ref,i| / E_ref,i, E the loop
//     energy. Significant: E_ref,i >= kSignificantCycleEnergy x the largest reference loop
//     (the nearly elastic cycles dissipate next to nothing; their relative error is noise);
//   peak_force: max over all cycles of |T_i - T_ref,i| / T_ref,i and |C_i - C_ref,i| / |C_ref,i|
//     (T, C: largest tension and compression of the cycle);
//   beta: max over the significant cycles of |beta_i - beta_ref,i| / beta_ref,i,
//     beta = |C| / T of the cycle (AISC 341 compression strength adjustment factor).
//   A run that completed fewer cycles than the reference has an infinite error.
// Frames (a time-history window):
//   peak_drift: max over stories of |d_s - d_ref,s| / d_ref,s (peak |story drift ratio|);
//   residual_drift: max over stories of |r_s - r_ref,s| / max_s d_ref,s: residual drifts are
//     often near zero, so they are measured against the largest reference peak drift;
//   cid: max over braces of |CID_b - CID_ref,b| / max(max_b CID_ref,b, 1 dy) (cumulative
//     inelastic deformation, dy; braces that stay elastic have CID near 0).
//   A run that stopped before the reference's end time has an infinite error.
// The primary error (the one the front and the acceptance use) is cycle_energy for a
// component and peak_drift for a frame; worst is the largest of the case's metrics.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace brb::study {

inline constexpr double kSignificantCycleEnergy = 0.05;

struct CycleResponse {
  double energy = 0.0;          ///< N mm
  double max_tension = 0.0;     ///< N
  double max_compression = 0.0; ///< N (negative)
  double amplitude = 0.0;       ///< mm (from the protocol)
};

struct ComponentResponse {
  bool completed = false;
  std::vector<CycleResponse> cycles; ///< completed cycles, in order
  int iterations = 0;
};

struct FrameResponse {
  bool completed = false;             ///< reached the end of the window without collapse or failure
  double end_time = 0.0;              ///< s
  std::vector<double> max_drift;      ///< per story
  std::vector<double> residual_drift; ///< per story
  std::vector<double> cid;            ///< per brace, dy
  int truss_braces = 0;               ///< after `auto`
  int full_braces = 0;
};

struct ParetoErrors {
  std::optional<double> cycle_energy, peak_force, beta;  ///< components
  std::optional<double> peak_drift, residual_drift, cid; ///< frames
  /// cycle_energy against the case's `brb solid` run (issue 6; solid_cycle_energy_error), where the
  /// matrix names one; not part of primary() or worst(), which measure against the finest
  /// `full` setting.
  std::optional<double> solid;

  /// cycle_energy or peak_drift (infinite when neither is known).
  double primary() const;
  /// The largest of the metrics that are known (infinite when none is).
  double worst() const;
};

ParetoErrors component_errors(const ComponentResponse& reference, const ComponentResponse& run);

/// Relative amplitude difference beyond which a cycle of the 3D run is not the same cycle.
inline constexpr double kSolidAmplitudeTolerance = 0.01;

/// The cycle-energy error of a completed run against a `brb solid` run of the same brace whose
/// protocol begins with the run's (it may go on: only the run's cycles are compared). Nothing
/// when the run did not complete, the 3D run has fewer cycles, or a cycle's amplitude differs
/// by more than kSolidAmplitudeTolerance (then the two did not follow the same protocol).
std::optional<double> solid_cycle_energy_error(const ComponentResponse& solid,
                                               const ComponentResponse& run);
ParetoErrors frame_errors(const FrameResponse& reference, const FrameResponse& run);

} // namespace brb::study
