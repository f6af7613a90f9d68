// `brb bench skips` (issue 9, DESIGN.md section 10): what each work skip of model::WorkSkips
// saves and what error it adds. Each skip is switched off alone, everything else on, and the
// run is compared with the all-on run on two scenes:
//   cyclic: the full (expanded) model of a restrained brace through a short cyclic protocol;
//   frame:  a window of a frame's time-history analysis with every brace as the full
//           condensed BRB element (the scene where open links and reused tangents act).
// `auto` is measured as the brace's `auto` choice (on) against the full model (off).
// Times: process CPU time per run, median of the repeats. Error: the largest difference of
// the compared histories over their largest magnitude (cyclic: the force at every step;
// frame: the story drifts and the base shear at every step), and whether they are identical
// bit for bit.
#pragma once

#include "brb/model/work_skips.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace brb::study {

struct SkipsStudyOptions {
  std::filesystem::path brace_file; ///< restrained brace of the cyclic scene (brace schema)
  int core_elements = 6;            ///< core elements of that brace (cost of the full model)
  std::vector<double> amplitudes_dy = {0.5, 1.0, 2.0}; ///< one full cycle each (dy)
  double max_step_dy = 0.1;                            ///< protocol step (dy)
  std::filesystem::path frame_file;                    ///< frame model file
  int frame_core_elements = 4;  ///< core elements of every brace in the frame scene
  std::filesystem::path record; ///< ground motion of the frame scene (AT2 or CSV)
  double record_scale = 1.0;
  double window = 0.1; ///< s: the first `window` seconds of the record
  int repeats = 3;
};

/// One skip on one scene.
struct SkipMeasurement {
  std::string skip;   ///< open_links, elastic_fast_path, reuse_tangents, requested_recorders, auto
  std::string scene;  ///< cyclic or frame
  bool exact = false; ///< the skip is exact by construction (zero error expected)
  bool applies = false;  ///< the scene has work this skip can skip
  double time_on = 0.0;  ///< s (CPU, median)
  double time_off = 0.0; ///< s (CPU, median)
  double relative_error = 0.0;
  bool identical = false; ///< compared histories equal bit for bit
  long hits = 0; ///< evaluations the skip answered (open links, reused tangents; -1 unknown)
  std::string note;

  double saved_fraction() const { return time_off > 0.0 ? 1.0 - time_on / time_off : 0.0; }
};

struct SkipsStudyResult {
  std::vector<SkipMeasurement> rows;
  int cyclic_steps = 0;
  int frame_steps = 0;
  std::string auto_choice_cyclic; ///< what `auto` picks for the cyclic scene's brace
  std::string auto_choice_frame;  ///< and for the frame's braces
};

/// Runs the study (minutes with the defaults). Throws io::InputError for unreadable inputs and
/// std::runtime_error when a run does not converge.
SkipsStudyResult run_skips_study(const SkipsStudyOptions& options);

/// Writes DIR/SKIPS.md and DIR/skips.csv atomically.
void write_skips_report(const std::filesystem::path& directory, const SkipsStudyOptions& options,
                        const SkipsStudyResult& result);

/// The skips in the order of the report, with the WorkSkips that has only that one off.
struct NamedSkip {
  std::string name;
  model::WorkSkips off;
  bool exact = false;
};
std::vector<NamedSkip> named_skips();

} // namespace brb::study
