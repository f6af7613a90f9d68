// `brb bench pareto`: the run-time-against-error study (issue 9; README "brb bench pareto").
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <ostream>
#include <vector>

namespace brb::cli {

struct BenchParetoCommand {
  /// Matrix files; none: every bench/pareto/*.json under the current directory.
  std::vector<std::filesystem::path> matrices;
  std::filesystem::path output_directory = "bench"; ///< PARETO.md and pareto.csv
  std::optional<int> repeats;                       ///< overrides the matrices' repeats
  int jobs = 1;
  bool quick = false;
  /// run the settings that name a committed run instead of reading it
  bool run_committed = false;
};

/// Registers `pareto` under the parent subcommand `bench`.
CLI::App* add_bench_pareto_command(CLI::App& bench, BenchParetoCommand& command);

/// Reads every matrix first (io::InputError: nothing run, nothing written), runs them, writes
/// PARETO.md and pareto.csv, prints the fronts. Returns 0, or 1 when a case's reference run
/// failed or stopped early (its errors cannot be measured; the outputs are written).
int run_bench_pareto_command(const BenchParetoCommand& command, std::ostream& report,
                             std::ostream& notes);

} // namespace brb::cli
