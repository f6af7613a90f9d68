// `brb check`: the AISC 341 check of a brace (README: "brb check").
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <ostream>

namespace brb::cli {

struct CheckCommand {
  std::filesystem::path check;            ///< CHECK.json (README: "brb check")
  std::filesystem::path output_directory; ///< receives check.json, check.md, hysteresis.csv
};

/// Registers the sub-command and its options (stored into `command` when parsed).
CLI::App* add_check_command(CLI::App& app, CheckCommand& command);

/// Runs it: reads and checks the check file (InputError on a bad one) before anything is
/// written, runs the qualification test (and the drift-capacity search when asked), writes
/// DIR/hysteresis.csv, DIR/check.json and DIR/check.md atomically and prints the verdict.
/// Returns the exit status: 0 whatever the verdict (the verdict is a result), 1 when the
/// analysis of the design drift stopped early.
int run_check_command(const CheckCommand& command, std::ostream& report, std::ostream& notes);

} // namespace brb::cli
