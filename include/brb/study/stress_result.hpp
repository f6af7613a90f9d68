// What a stress case gave (issue 9): whether it completed (or why not), the NaNs found in
// its outputs and state, its energy-balance error, the solver fallbacks it used, and the
// wall time of each step. The acceptance of the issue is acceptable(): no NaN, completed or
// an explicit failure reason, energy-balance error under 1 % of the input work.
#pragma once

#include "brb/study/stress_case.hpp"

#include <string>
#include <vector>

namespace brb::study {

/// Energy-balance error allowed by the acceptance: 1 % of the input work.
inline constexpr double kEnergyErrorLimit = 0.01;

/// Fallbacks a case needed, as the solvers report them.
struct FallbackCounts {
  /// Brace (StaticAnalysis): converged substeps beyond one per step (the step was cut).
  /// Frame (TransientAnalysis): steps that were retried in halved substeps.
  int substeps = 0;
  /// brace: substeps cut by the far-branch control (NewtonSettings::max_correction_ratio and
  /// the dissipation-supplied-by-work test: Newton landed away from the tangent's prediction).
  /// A cause of `substeps` (each cut's halves are counted there), so not added to total().
  int far_branch_cuts = 0;
  int pseudo_transient = 0;  ///< brace: substeps passed by pseudo-transient continuation
  int unstable_accepted = 0; ///< brace: substeps accepted with an unstable tangent
  /// brace: substeps cut by the energy-error guard; a cause of `substeps` too (not in total()).
  int energy_cuts = 0;
  int modified_newton = 0; ///< frame: steps that switched to modified Newton
  int broyden = 0;         ///< frame: steps that switched to Broyden's update
  int total() const {
    return substeps + pseudo_transient + unstable_accepted + modified_newton + broyden;
  }
};

/// Median, 90th percentile and largest of a set of wall times (s); zeros when empty.
struct TimeDistribution {
  double median = 0.0;
  double p90 = 0.0;
  double max = 0.0;
};
/// Nearest-rank percentiles: the value of rank ceil(p n) of the sorted times.
TimeDistribution distribution_of(std::vector<double> times);

struct StressResult {
  std::string name;
  StressGroup group = StressGroup::random_history;
  bool completed = false;     ///< every step was reached (a frame: or it collapsed)
  bool collapsed = false;     ///< frame: a story drift exceeded the drift limit (a result)
  std::string failure_reason; ///< why it did not complete (empty when it did)
  std::string outcome;        ///< one line: "completed", "collapse at ...", the failure
  /// Non-finite numbers found in the outputs and the final state (must be 0).
  int nan_count = 0;
  /// |external work - stored - dissipated| / input work at the end of the run. Brace: the
  /// energy released in jumps counts as dissipated, and the input work is the gross work
  /// (sum over the substeps of |work|, EnergyBalance::gross_work: the net work after nearly
  /// elastic cycles is close to zero). Frame: kinetic and damping energies are on the
  /// right-hand side, the static work on the left, and the input work is the ground
  /// motion's (FrameRunResult::energy_balance_error).
  double energy_error = 0.0;
  double input_work = 0.0; ///< N mm, the denominator of energy_error
  FallbackCounts fallbacks;
  int steps = 0;                       ///< steps that converged
  int planned_steps = 0;               ///< steps the case asks for
  std::vector<double> step_wall_times; ///< s, one per converged step
  /// s, the step that failed (every fallback tried), when one did: not in step_wall_times.
  double failed_step_wall_time = 0.0;
  double wall_time = 0.0;  ///< s, the whole case (building included)
  std::string notes;       ///< e.g. peak drift, core strain reached
  double peak_drift = 0.0; ///< frame: largest story drift ratio reached

  TimeDistribution step_times() const { return distribution_of(step_wall_times); }
  /// The acceptance for this case: no NaN, completed or a stated failure reason,
  /// energy error < kEnergyErrorLimit.
  bool acceptable() const;
  /// Why acceptable() is false ("" when it is true).
  std::string acceptance_failure() const;
};

} // namespace brb::study
