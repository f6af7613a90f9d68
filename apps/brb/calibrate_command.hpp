// `brb calibrate`: fit a brace's core steel (fy, two Chaboche back-stresses, Voce) to a
// laboratory force-deformation record with the fast axial model of the brace
// (validation/steel_calibration.hpp); README: "brb calibrate".
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>

namespace brb::cli {

struct CalibrateCommand {
  std::filesystem::path brace;  ///< BRACE.json: geometry and starting steel
  std::filesystem::path record; ///< JSON with the record reference (a metrics.json or a bare one)
  std::filesystem::path output; ///< PARAMS.json
  std::optional<std::filesystem::path> protocol_output;  ///< protocol.csv to write
  std::optional<std::filesystem::path> shared_directory; ///< for "shared:" record paths
  std::string side = "tension";                          ///< "tension" or "all"
  int max_evaluations = 3000;
  double reversal_threshold = 0.1; ///< dy
  double max_step = 0.0999;        ///< dy, just under brb cyclic's default dy / 10
  double energy_floor = 0.05;      ///< fraction of the largest test loop energy
};

CLI::App* add_calibrate_command(CLI::App& app, CalibrateCommand& command);

/// Reads the brace and the record, extracts the protocol, calibrates, writes PARAMS.json (and
/// the protocol CSV when asked) atomically and prints a summary on `report`. Returns 0.
int run_calibrate_command(const CalibrateCommand& command, std::ostream& report);

} // namespace brb::cli
