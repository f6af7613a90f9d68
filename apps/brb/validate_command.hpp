// `brb validate`: runs the validation specimens and writes the report (README "brb validate").
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace brb::cli {

struct ValidateCommand {
  std::filesystem::path directory; ///< the validation folder, one sub-folder per specimen
  std::vector<std::string> only;   ///< specimen ids to run (all when empty)
  std::vector<int> refinements;    ///< overrides every specimen's list when not empty
  std::optional<std::filesystem::path> report; ///< REPORT.md's place (default DIR/REPORT.md)
  std::filesystem::path shared_directory;      ///< resolves "shared:" paths
  int jobs = 1;    ///< runs at a time (each run is independent; results do not depend on it)
  int threads = 1; ///< element-loop threads of each run (results do not depend on it)
  /// Seconds between the progress lines of each run (none when empty; ProgressLine)
  std::optional<double> progress_interval;
  /// `--checkpoint-dir DIR`: each run keeps a checkpoint DIR/<id>_x<k>.checkpoint, takes up
  /// from it when it exists, writes it at most every checkpoint_interval seconds of wall time
  /// and removes it once its outputs are written (validation/README: the x4 lab records).
  std::optional<std::filesystem::path> checkpoint_directory;
  double checkpoint_interval = 600.0;
};

/// Registers the sub-command and its options (stored into `command` when parsed).
CLI::App* add_validate_command(CLI::App& app, ValidateCommand& command);

/// Reads every selected specimen (InputError on a bad file, before any run), runs each at
/// each refinement (outputs in DIR/<id>/out/x<k>/), writes the report (Markdown and JSON,
/// atomically) and prints progress and the summary on `report`. Returns 0 when every check
/// passed, 1 when one failed.
int run_validate_command(const ValidateCommand& command, std::ostream& report);

} // namespace brb::cli
