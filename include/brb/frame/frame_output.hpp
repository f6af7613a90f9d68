// Outputs of `brb frame`: one CSV per history asked (drifts.csv, floor_accelerations.csv,
// base_shear.csv, energy.csv, braces.csv) and summary.json (README "brb frame"). Every file
// is written atomically (temporary file + rename); summary.json last, so its presence means
// the run's outputs are complete.
#pragma once

#include "brb/frame/frame_model.hpp"
#include "brb/frame/frame_run.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>

namespace brb::frame {

/// What the summary says about how the run was set up.
struct FrameRunDescription {
  std::string model_file;
  std::string motion_file;
  double scale = 1.0;
  std::string integrator; ///< "newmark", "hht" or "explicit"
  double dt = 0.0;        ///< s, analysis time step
  double wall_time = 0.0; ///< s
  /// every brace's core element count when the run overrode its brace file's (brb frame
  /// --core-elements); nothing: the files' own
  std::optional<int> core_elements;
};

nlohmann::ordered_json frame_summary_json(const FrameModel& frame, const FrameRunResult& result,
                                          const FrameRunDescription& description);

/// Writes the histories of `result` and summary.json into `directory` (which must exist).
void write_frame_outputs(const std::filesystem::path& directory, const FrameModel& frame,
                         const FrameRunResult& result, const FrameRunDescription& description);

} // namespace brb::frame
