// `brb cyclic`: a virtual cyclic test of a brace under a loading protocol (README: "brb cyclic").
#pragma once

#include "brb/analysis/static_analysis.hpp"
#include "brb/model/brace_model.hpp"
#include "brb/model/brace_spec.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace brb::cli {

struct CyclicCommand {
  std::filesystem::path brace;            ///< BRACE.json (README: "Brace files")
  std::filesystem::path protocol;         ///< P.json or P.csv (README: "Loading protocols")
  std::filesystem::path output_directory; ///< receives hysteresis.csv and summary.json
  /// mm: the largest deformation change per step when the protocol gives none (default dy / 10).
  std::optional<double> max_step;
  /// Energy-error control of the solver (NewtonSettings::energy_tolerance; default its guard
  /// value 1e-2); 0 turns it off. Tight values cost many substeps on restrained cores
  /// (README, "Energy balance").
  double energy_tolerance = analysis::NewtonSettings::kEnergyGuard;
  /// Balance control (NewtonSettings::balance_tolerance; default off).
  double balance_tolerance = 0.0;
  /// Also write DIR/element_history.csv: the element outputs after every step.
  bool histories = false;
  /// Also write DIR/shape.csv: the deformed shape after these steps (hysteresis.csv's step
  /// numbers) and after the last converged step.
  std::optional<std::vector<int>> shape_steps;
  /// Print a progress line on the notes stream at most every this many seconds of wall time
  /// (0: after every step) and after the last step; none: no progress lines.
  std::optional<double> progress_interval;
  /// `--checkpoint FILE`: the run takes up from FILE when it exists (written for the same
  /// brace and protocol files and settings), writes it at most every checkpoint_interval
  /// seconds of wall time, and removes it once the outputs are written.
  std::optional<std::filesystem::path> checkpoint;
  double checkpoint_interval = 600.0;
  /// Threads evaluating the elements (NewtonSettings::element_threads; results do not
  /// depend on it).
  int threads = 1;
};

/// The brace's name in the outputs: its "name", or the brace file's name without extension.
std::string brace_name(const model::BraceSpec& spec, const std::filesystem::path& file);

/// The brace's finite element model (full or truss, as its "element" says); a ParameterError
/// becomes an InputError at the JSON path of `file` it names. `brb solid` takes its dy and Py
/// from it, so the 3D and the reduced model follow the same protocol points.
model::BraceModel build_brace(const model::BraceSpec& spec, const std::filesystem::path& file);

/// Adds `--max-step MM` (a finite number of mm > 0, stored into `max_step`) to a command that
/// reads a loading protocol.
void add_max_step_option(CLI::App& command, std::optional<double>& max_step,
                         const std::string& description);

/// Registers the sub-command and its options (stored into `command` when parsed).
CLI::App* add_cyclic_command(CLI::App& app, CyclicCommand& command);

/// Runs it: reads and checks every input (InputError on a bad one) before anything is written,
/// runs the test, writes DIR/hysteresis.csv and DIR/summary.json atomically (also when the
/// analysis stopped early), prints the text summary on `report` and, when the analysis stopped
/// early, the reason on `notes`. Returns the exit status: 0 completed, 1 stopped early.
int run_cyclic_command(const CyclicCommand& command, std::ostream& report, std::ostream& notes);

} // namespace brb::cli
