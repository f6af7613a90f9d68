// `brb solid`: the virtual cyclic test of a brace's 3D continuum model (README: "brb solid").
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <ostream>
#include <vector>

namespace brb::cli {

struct SolidCommand {
  std::filesystem::path brace;             ///< BRACE.json, with an optional "solid" block
  std::filesystem::path protocol;          ///< P.json or P.csv (as brb cyclic)
  std::filesystem::path output_directory;  ///< hysteresis.csv, summary.json, energies.csv, fields
  std::optional<double> max_step;          ///< mm; default dy / 10 (as brb cyclic)
  int outputs_per_step = 1;                ///< records per protocol step
  double time_per_deformation = 0.0;       ///< s/mm; 0: the run's default (20 T_1 per dy)
  double duration = 0.0;                   ///< s; 0: from time_per_deformation
  double min_excursion_time = 0.0;         ///< s; 0: no floor on an excursion's duration
  double lateral_damping = 0.0;            ///< 1/s; 0: no lateral mass damping
  std::optional<int> threads;              ///< overrides the solid block's threads
  std::vector<int> snapshot_steps;         ///< hysteresis steps written as .vtu
  int snapshot_every = 0;                  ///< also every N-th step (0: off)
  bool histories = false;                  ///< write element_history.csv
  std::optional<double> progress_interval; ///< s of wall time between progress lines
};

CLI::App* add_solid_command(CLI::App& app, SolidCommand& command);

/// Reads and checks every input before anything is written, runs the 3D model, writes the
/// outputs atomically (also when it stopped early) and prints a summary. Returns 0 completed,
/// 1 stopped early.
int run_solid_command(const SolidCommand& command, std::ostream& report, std::ostream& notes);

} // namespace brb::cli
