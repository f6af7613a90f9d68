// `brb bench skips` and `brb bench scaling` (issue 9): what each work skip saves and costs,
// and how the cost of a frame analysis grows with its braces and its record (README
// "Work skips and cost scaling"). Sub-commands of `brb bench`.
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace brb::cli {

struct BenchSkipsCommand {
  std::filesystem::path brace = "examples/braces/girona_D3_restrained.json";
  int core_elements = 6;
  std::vector<double> amplitudes = {0.5, 1.0, 2.0}; ///< dy
  double max_step = 0.1;                            ///< dy
  std::filesystem::path frame = "frames/brbf3/model.json";
  int frame_core_elements = 4;
  std::filesystem::path record; ///< default: the shared Pacoima Dam record
  double scale = 1.0;
  double window = 0.1; ///< s
  int repeats = 3;
  std::filesystem::path output_directory;
};

struct BenchScalingCommand {
  std::filesystem::path frame = "frames/brbf3/model.json";
  std::filesystem::path record; ///< default: the shared Pacoima Dam record
  double scale = 1.0;
  std::vector<int> brace_counts = {1, 4, 16, 64};
  double series_length = 5.0; ///< s
  std::vector<double> lengths = {2.5, 5.0, 10.0, 20.0};
  int length_braces = 4;
  std::string fidelity = "truss";
  int repeats = 3;
  std::filesystem::path output_directory;
};

/// Adds `skips` and `scaling` under `bench` (the parent sub-command).
CLI::App* add_bench_skips_command(CLI::App& bench, BenchSkipsCommand& command);
CLI::App* add_bench_scaling_command(CLI::App& bench, BenchScalingCommand& command);

/// Run the studies, write DIR/SKIPS.md + skips.csv (DIR/SCALING.md + scaling.csv) and print
/// the table. Returns 0; input errors throw io::InputError (exit 2), failed runs
/// std::runtime_error (exit 1).
int run_bench_skips_command(const BenchSkipsCommand& command, std::ostream& report);
int run_bench_scaling_command(const BenchScalingCommand& command, std::ostream& report);

} // namespace brb::cli
