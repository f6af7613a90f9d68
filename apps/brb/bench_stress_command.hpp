// `brb bench stress`: the numerical stress suite (issue 9; README "Numerical stress tests"):
// random deformation histories, monotonic compression to 10 % core strain, step sizes from
// 1/100 to 10 x the default, a frame at and beyond its collapse intensity and near-singular
// braces; writes DIR/stress_report.md and DIR/stress_cases.csv.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace brb::cli {

struct BenchStressCommand {
  std::filesystem::path output_directory = ".";
  bool long_suite = false;
  std::uint64_t seed = 1;
  int jobs = 1;
  std::filesystem::path brace;  ///< default: examples/braces/girona_D3_restrained.json
  std::filesystem::path frame;  ///< default: frames/brbf3/model.json
  std::filesystem::path record; ///< default: the shared Rinaldi228.AT2
  /// Hidden (tests): run only the cases whose name contains one of these texts.
  std::vector<std::string> only;
};

/// Registers `stress` under the `bench` parent command.
CLI::App* add_bench_stress_command(CLI::App& bench, BenchStressCommand& command);

/// Builds the suite (InputError on a bad input or option, before any run), runs it, writes
/// the report files and prints the totals. Returns 0 when every case meets the acceptance,
/// 1 when one does not.
int run_bench_stress_command(const BenchStressCommand& command, std::ostream& out);

} // namespace brb::cli
