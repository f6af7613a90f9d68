// The settings matrix of the run-time-against-error study (`brb bench pareto`, issue 9): one
// case (a component test of a brace under a protocol, or a frame under a ground-motion
// window) and the settings it is run at (fidelity, core elements, fibers, element mode, step).
// Each setting's error is measured against the case's reference: the finest `full` setting of
// the matrix (or the one the file names).
//
// Matrix file (JSON, comments allowed; paths relative to the matrix file; unknown keys are
// errors; every error names the file, the JSON path and what was expected):
//
//   { "name": "girona_D3", "kind": "component",     // or "frame"
//     "description": "...",                         // optional, quoted in PARETO.md
//     "brace": "../../validation/girona_D3/brace.json", "protocol": "d3_protocol.json",
//     "solid": "../../validation/solid_girona_D3/solid/x1/summary.json",  // optional: the
//         // summary.json of a `brb solid` run of the brace under a protocol that begins with
//         // the case's (components; the column "vs `brb solid`")
//     // frame: "model": "...model.json", "motion": "...AT2", "scale": 1, "duration": 4,
//     "repeats": 3,                                 // optional, default 1
//     "reference": "full-16",                       // optional: default the finest full
//     "auto_rule": "derive",                        // or "check": role of the case for `auto`
//     "quick": {"duration": 0.5} or {"protocol": "..."},   // optional, for --quick
//     "settings": [
//       {"label": "truss", "fidelity": "truss"},
//       {"label": "full-16", "fidelity": "full", "core_elements": 16, "fibers": [4, 16],
//        "integration_points": 3, "mode": "condensed", "max_step": 0.1 /* dy,
//        components */, "dt": 0.005 /* s, frames */, "repeats": 1,
//        "committed_run": "reference/brbf9_full16/summary.json" /* frames, optional */}
//     ] }
//
// committed_run (frames): the summary.json of a `brb frame` run of this very setting (the
// matrix's model, record, scale and window, the setting's dt, core elements and fidelity),
// committed because it costs too long to repeat with every study (a frame with 16-element full
// braces: an hour and more on the 2-core machine). The study reads its drifts, brace CIDs and wall
// time instead of running it (`brb bench pareto --run-committed` runs it anyway); the file must
// agree with the case and the setting (read_committed_frame_run checks it).
//
// Contact (gap-link) spacing is not a separate axis: the brace model ties one link to every
// core station, so it follows `core_elements` (spacing = yielding length / core_elements).
#pragma once

#include "brb/model/brace_spec.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace brb::study {

enum class CaseKind { component, frame };
enum class SettingFidelity { truss, full, automatic };
/// Whether a case was used to derive the `auto` rule or only to check it.
enum class AutoRuleRole { derive, check };

/// One point of the matrix. Absent values keep the brace's (or the frame model's) own.
struct ParetoSetting {
  std::string label;
  SettingFidelity fidelity = SettingFidelity::full;
  std::optional<int> core_elements;
  std::optional<std::pair<int, int>> fibers; ///< core section fiber counts (a, b)
  std::optional<int> integration_points;
  /// full braces: frames default condensed, components expanded (analysis/condensed_brace.hpp)
  model::ElementMode mode = model::ElementMode::condensed;
  std::optional<double> max_step; ///< dy, components only
  std::optional<double> dt;       ///< s, frames only
  std::optional<int> repeats;     ///< overrides the case's
  /// frames, optional: summary.json of a committed `brb frame` run of this setting (above)
  std::optional<std::filesystem::path> committed_run;

  /// The brace as this setting builds it (core elements, fibers, integration points).
  model::BraceSpec applied_to(model::BraceSpec brace) const;
};

struct ParetoCase {
  std::string name;
  CaseKind kind = CaseKind::component;
  std::string description;
  std::filesystem::path matrix_file;
  std::filesystem::path brace;    ///< component
  std::filesystem::path protocol; ///< component
  /// component, optional: summary.json of a `brb solid` run of the brace (see above)
  std::optional<std::filesystem::path> solid;
  std::filesystem::path model;  ///< frame
  std::filesystem::path motion; ///< frame
  double scale = 1.0;           ///< frame: factor on the record
  double duration = 0.0;        ///< s, frame: the window from the record's start (> 0)
  int repeats = 1;
  AutoRuleRole auto_rule = AutoRuleRole::derive;
  std::optional<double> quick_duration;                ///< frame, for --quick
  std::optional<std::filesystem::path> quick_protocol; ///< component, for --quick
  std::vector<ParetoSetting> settings;
  std::size_t reference = 0; ///< index in settings

  /// The case as --quick runs it: the quick window or protocol, one repeat, committed runs run.
  ParetoCase quick() const;
};

/// "truss", "full", "auto"; "component", "frame".
std::string to_string(SettingFidelity fidelity);
std::string to_string(CaseKind kind);

/// The finest `full` setting: most core elements, then most fibers, then most integration
/// points, then the smallest step; the first of equals. Nothing when no setting is `full`.
std::optional<std::size_t> finest_full_setting(const std::vector<ParetoSetting>& settings);

/// Reads and checks a matrix file (schema above); the files it names must exist. Throws
/// io::InputError naming the file and JSON path.
ParetoCase read_pareto_matrix(const std::filesystem::path& file);

} // namespace brb::study
