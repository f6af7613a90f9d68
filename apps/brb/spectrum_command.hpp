// `brb spectrum`: the 5 %-damped (or other) pseudo-acceleration response spectrum of a ground
// motion by the exact piecewise-linear SDOF solution (README "brb spectrum").
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>

namespace brb::cli {

struct SpectrumCommand {
  std::filesystem::path motion;     ///< the record (.AT2, .csv, .rec/.txt)
  std::optional<std::string> units; ///< g, m/s^2, mm/s^2 (overrides an AT2 header)
  std::optional<double> dt;         ///< s, for files without a time step
  double scale = 1.0;               ///< applied after the units
  double damping_ratio = 0.05;      ///< zeta
  std::string format = "auto";      ///< auto, at2, csv, column
  std::filesystem::path output;     ///< CSV period,Sa_g
};

/// Registers the sub-command and its options (stored into `command` when parsed).
CLI::App* add_spectrum_command(CLI::App& app, SpectrumCommand& command);

/// Reads the record (InputError on a bad one), computes Sa at 100 log-spaced periods per
/// decade from 0.01 s to 10 s, writes the CSV atomically and a one-line summary on `notes`.
/// Returns the exit status.
int run_spectrum_command(const SpectrumCommand& command, std::ostream& notes);

} // namespace brb::cli
