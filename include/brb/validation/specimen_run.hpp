// Running a validation specimen at one mesh refinement and judging its metrics: the virtual
// cyclic test of its brace under its protocol, the automatic checks every run gets
// (completion, energy balance) and the metrics of metrics.json.
#pragma once

#include "brb/analysis/cyclic_test.hpp"
#include "brb/model/brace_spec.hpp"
#include "brb/validation/metric_kinds.hpp"
#include "brb/validation/specimen.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace brb::validation {

/// The energy balance's relative error every run must stay below (the target; the
/// solver's present accuracy is reported against it, never the other way round).
inline constexpr double energy_balance_tolerance = 1e-6;

enum class CheckStatus {
  pass,
  fail,
  reported ///< a value without a reference or bound: shown, not judged
};

/// "pass", "FAIL", "reported".
std::string to_string(CheckStatus status);

/// One judged (or reported) quantity of a run.
struct CheckResult {
  std::string name;
  std::string kind; ///< a metric kind, or "completion" / "energy_balance" (automatic)
  std::string unit;
  std::optional<double> value;
  std::optional<double> reference;
  std::optional<Tolerance> tolerance;
  std::optional<double> at_least;
  std::optional<double> at_most;
  std::optional<bool> expected;
  /// result - reference, divided by |reference| when the tolerance is relative.
  std::optional<double> error;
  CheckStatus status = CheckStatus::reported;
  std::string note;   ///< where the value comes from, or why there is none
  std::string source; ///< of the reference
};

/// Compares a metric's value with its reference, bounds or expected flag. A metric that has
/// a check but no value (e.g. its cycle was not reached) fails.
CheckResult judge(const MetricSpec& metric, const MetricValue& value);

/// The automatic checks of a run: the protocol ran to its end; the energy balance's relative
/// error is at most energy_balance_tolerance.
std::vector<CheckResult> automatic_checks(const analysis::CyclicTestResult& result);

/// The checks of a reference itself: for a `brb solid` run, its largest kinetic and hourglass
/// energies over the internal energy (its summary.json) at most kQuasiStaticRatioLimit, issue
/// 6's quasi-static check (none when the summary does not give them).
std::vector<CheckResult> reference_checks(const RecordReference& reference);

/// The brace with every zone's element count (core, transition, connection; the casing
/// follows the core) multiplied by `refinement` (>= 1).
model::BraceSpec refined(const model::BraceSpec& spec, int refinement);

/// A specimen whose brace and protocol were read and checked (before any run).
struct PreparedSpecimen {
  Specimen specimen;
  model::BraceSpec brace;
  double yield_deformation = 0.0; ///< mm
  double yield_force = 0.0;       ///< N
  std::size_t protocol_points = 0;
  /// The lab record at the protocol's points (specimens with a reference record).
  std::optional<RecordSeries> record;
};

/// Reads and checks the brace and protocol files of `specimen` (io::InputError naming the
/// file and JSON path), so that every input error shows before the first run.
PreparedSpecimen prepare_specimen(Specimen specimen);

/// What one run gave.
struct RunOutcome {
  int refinement = 1;
  int core_elements = 0;
  std::filesystem::path output_directory; ///< holds hysteresis.csv and summary.json
  bool completed = false;
  std::string stop_reason;
  int steps = 0;         ///< converged steps
  int planned_steps = 0; ///< points of the protocol minus one
  int iterations = 0;
  double run_seconds = 0.0; ///< wall-clock time of the analysis (not of writing)
  /// Steps a checkpoint of an earlier run had converged (0: run from the start); run_seconds
  /// then includes that run's time.
  int resumed_from_step = 0;
  double energy_balance_error = 0.0;
  /// EnergyBalance::relative_misfit: the laws' time discretisation, reported.
  double integration_misfit = 0.0;
  double yield_deformation = 0.0;
  double yield_force = 0.0;
  std::vector<CheckResult> checks; ///< automatic checks first, then the metrics in file order
};

/// Runs `prepared` at `refinement`, writes hysteresis.csv and summary.json (the files of
/// `brb cyclic`) into `output_directory` (created with its parents), and judges the checks.
/// `observer` is called after every converged step (e.g. progress lines).
/// `checkpoint`: a checkpoint file for this run (`brb validate --checkpoint-dir`): taken up if
/// it exists and was written for the same specimen files, refinement and solver settings,
/// written at most every `checkpoint_interval` seconds, removed once the outputs are written.
/// `element_threads`: NewtonSettings::element_threads of the run (the same results for any).
RunOutcome run_specimen(const PreparedSpecimen& prepared, int refinement,
                        const std::filesystem::path& output_directory,
                        analysis::StepObserver observer = {},
                        const std::optional<std::filesystem::path>& checkpoint = std::nullopt,
                        double checkpoint_interval = 600.0, int element_threads = 1);

/// The checks of a finished cyclic test (automatic ones, then the metrics): the part of
/// run_specimen after the analysis, usable on any result.
std::vector<CheckResult> evaluate_checks(const Specimen& specimen, const RunData& run);

} // namespace brb::validation
