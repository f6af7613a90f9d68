// Runs a pareto matrix (pareto_matrix.hpp): every setting `repeats` times, the wall time of
// each run (model build + analysis; reading the inputs is done once, before), the median of
// the repeats, the response of the first run, and its errors against the reference setting
// (pareto_metrics.hpp). Runs go on `jobs` threads; with more than one job the runs share the
// machine's cores, so their wall times are those of a loaded machine.
#pragma once

#include "brb/study/pareto_matrix.hpp"
#include "brb/study/pareto_metrics.hpp"

#include <functional>
#include <string>
#include <vector>

namespace brb::study {

struct SettingOutcome {
  ParetoSetting setting;
  bool ran = false; ///< every repeat finished its analysis (it may have stopped early)
  /// read from the setting's committed `brb frame` run (committed_run), not run by this study
  bool committed = false;
  std::string failure;            ///< why a run threw (empty when ran)
  std::vector<double> wall_times; ///< s, one per repeat
  double median_time = 0.0;       ///< s
  /// What `auto` (or the setting) built: "truss", "full", or for frames "6 truss; 0 full".
  std::string built_as;
  std::string auto_reason; ///< why `auto` chose it (first brace)
  ComponentResponse component;
  FrameResponse frame;
  std::string stop_reason;    ///< empty when the analysis went to its end
  ParetoErrors errors;        ///< against the reference
  bool front_primary = false; ///< on the front of (median time, primary error)
  bool front_worst = false;   ///< on the front of (median time, worst error)
};

/// A `brb solid` run of a component case's brace (the matrix's "solid"): its completed cycles
/// and its wall time.
struct SolidReference {
  std::filesystem::path file; ///< its summary.json
  ComponentResponse response;
  double run_seconds = 0.0;
};

/// Reads the cycles ("cycles": amplitude, energy, max_tension, max_compression), "completed"
/// and "solid"/"run_seconds" of a `brb solid` summary.json; io::InputError naming the file and
/// the field otherwise.
SolidReference read_solid_reference(const std::filesystem::path& summary_file);

/// A committed `brb frame` run of a frame case's setting (ParetoSetting::committed_run).
struct CommittedFrameRun {
  std::filesystem::path file; ///< its summary.json
  FrameResponse response;
  double wall_time = 0.0;  ///< s, as the run recorded it (model build + analysis)
  std::string built_as;    ///< "0 truss; 18 full"
  std::string stop_reason; ///< empty when it went to its end
};

/// What a run of a frame setting must show beyond the matrix's model, record and scale.
struct FrameRunExpectation {
  double dt = 0.0;       ///< s, the setting's analysis step
  double duration = 0.0; ///< s, the window plus the model's free vibration
  /// the core element count all the frame's brace files give (nothing when they differ)
  std::optional<int> file_core_elements;
};

/// Reads a `brb frame` summary.json as the run of `setting` of `study_case`, with the step,
/// analysed time and brace files of `expected`. io::InputError naming the file and the field when a
/// field is missing or the run is not of this case and setting: another model (its folder and file
/// name), record (file name), scale, analysed time (duration), step, core element count (the run's
/// `core_elements`, or the files' when it is null, against the setting's, or the files'), or brace
/// fidelity (a `full` or `truss` setting needs every brace built so).
CommittedFrameRun read_committed_frame_run(const std::filesystem::path& summary_file,
                                           const ParetoCase& study_case,
                                           const ParetoSetting& setting,
                                           const FrameRunExpectation& expected);

struct CaseOutcome {
  ParetoCase study_case;
  std::optional<SolidReference> solid;  ///< component, when the matrix names one
  std::vector<SettingOutcome> settings; ///< in the matrix's order
  double yield_deformation = 0.0;       ///< mm, component (of the reference brace)
  std::string window;                   ///< what was analysed, in words
};

struct ParetoRunOptions {
  int jobs = 1;               ///< threads (>= 1)
  std::optional<int> repeats; ///< overrides every setting's and case's repeats
  /// run the settings that name a committed run instead of reading it
  bool run_committed = false;
  /// Called after each run (from the worker thread, serialised): a line of progress.
  std::function<void(const std::string&)> progress;
};

/// The median of `values` (the mean of the two middle ones for an even count); 0 for none.
double median(std::vector<double> values);

/// Reads every case's inputs (io::InputError on a bad one), then runs all their settings from
/// one pool of `jobs` threads (costly runs first), and measures errors and fronts per case.
std::vector<CaseOutcome> run_pareto_cases(const std::vector<ParetoCase>& cases,
                                          const ParetoRunOptions& options);

/// run_pareto_cases for one case: reads the case's inputs (brace, protocol, frame model, record:
/// io::InputError on a bad one), runs every setting and measures its errors and the fronts.
CaseOutcome run_pareto_case(const ParetoCase& study_case, const ParetoRunOptions& options);

/// Errors against the reference and the fronts, from the runs' responses and times (used by
/// run_pareto_case; public so that the fronts can be tested on hand-made outcomes).
void evaluate_case(CaseOutcome& outcome);

} // namespace brb::study
