// `brb material`: one material point driven through a strain history (README: "brb material").
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <ostream>
#include <string>

namespace brb::cli {

struct MaterialCommand {
  std::string law;                      ///< steel, steel3d-collapsed, mortar, mortar3d-collapsed
  std::filesystem::path parameters;     ///< p.json
  std::filesystem::path strain_history; ///< CSV with a column `strain`
  std::filesystem::path output;         ///< CSV strain,stress,tangent,damage
};

/// Registers the sub-command and its options (stored into `command` when parsed).
CLI::App* add_material_command(CLI::App& app, MaterialCommand& command);

/// Runs it: reads the inputs (InputError on a bad one), drives the point, writes the output
/// atomically. Notes (substepping) go to `notes`. Returns the exit status.
int run_material_command(const MaterialCommand& command, std::ostream& notes);

} // namespace brb::cli
