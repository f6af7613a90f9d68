// `brb ida`: incremental dynamic analysis of a frame over a ground-motion suite (README
// "brb ida"): hunt-and-fill per record, runs on a thread pool (or MPI ranks), a journal that
// makes the study resumable, and the IDA outputs.
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>

namespace brb::cli {

struct IdaCommand {
  std::filesystem::path model;
  std::filesystem::path suite;
  std::filesystem::path output_directory;
  int jobs = 0; ///< 0: every core
  bool resume = false;
  std::string measure = "sa";
  std::optional<double> period;
  double damping_ratio = 0.05;
  double first = 0.2;
  double step = 0.2;
  double step_growth = 0.2;
  double resolution = 0.05;
  int max_runs = 12;
  double max_intensity = 0.0;
  std::optional<double> drift_limit;
  std::optional<double> mce;
  std::optional<std::string> braces;
  bool quiet = false;
};

CLI::App* add_ida_command(CLI::App& app, IdaCommand& command);

/// Checks every input before the first run (InputError), runs the IDA (threads, or MPI when
/// launched by mpirun with several ranks), writes the outputs. Progress lines go to `notes`.
int run_ida_command(const IdaCommand& command, std::ostream& report, std::ostream& notes);

} // namespace brb::cli
