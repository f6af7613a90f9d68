// Checkpoints of long runs on the command line: `brb cyclic --checkpoint FILE` and `brb
// validate --checkpoint-dir DIR`, with `--checkpoint-every SECONDS` (README, "Checkpoints").
#pragma once

#include <CLI/CLI.hpp>

namespace brb::cli {

/// Registers `--checkpoint-every SECONDS` (a number > 0, stored into `interval`).
void add_checkpoint_interval_option(CLI::App& command, double& interval);

} // namespace brb::cli
