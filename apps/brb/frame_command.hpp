// `brb frame`: a nonlinear time-history analysis of a frame model under a ground motion
// (README: "brb frame").
#pragma once

#include "brb/frame/frame_run.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>

namespace brb::cli {

struct FrameCommand {
  std::filesystem::path model;  ///< MODEL.json (README: "Frame model files")
  std::filesystem::path motion; ///< ground motion along the model's first direction
  /// Components along the model's second and third ground-motion directions (e.g. "y" and
  /// the vertical "z"; README "Frame model files", ground_motion).
  std::optional<std::filesystem::path> motion_2;
  std::optional<std::filesystem::path> motion_3;
  double scale = 1.0;               ///< factor on the record(s)
  std::optional<std::string> units; ///< g, m/s^2, mm/s^2 (AT2: from the header by default)
  std::optional<double> record_dt;  ///< s, for single-column records
  std::optional<double> duration;   ///< s, analyse only the first part of the record
  /// s, the analysis time step instead of the model's analysis.dt (a step-size study, or a
  /// reference run at the step of `brb bench pareto`'s settings)
  std::optional<double> step;
  /// Every brace's core element count instead of its brace file's (a mesh study of a frame's
  /// full braces; the contact links follow the core stations)
  std::optional<int> core_elements;
  /// s of wall time between progress lines on stderr (the first after as long); 0: none
  double progress_interval = 30.0;
  /// Overrides every brace's fidelity: elastic, truss, full or auto.
  std::optional<std::string> braces;
  std::filesystem::path output_directory;
};

CLI::App* add_frame_command(CLI::App& app, FrameCommand& command);

/// The progress line `brb frame` writes on stderr: time reached, steps, peak drift, the run
/// time so far (`elapsed`, s) and the time left at the mean rate so far.
std::string progress_line(const frame::FrameProgress& progress, double elapsed);

/// Reads and checks every input first (InputError: nothing written), runs the analysis,
/// writes the histories and DIR/summary.json, prints the peak drifts. Returns 0 when the run
/// completed (or stopped at a collapse it detected), 1 when a step failed after every fallback.
int run_frame_command(const FrameCommand& command, std::ostream& report, std::ostream& notes);

} // namespace brb::cli
