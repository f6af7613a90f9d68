// `--out DIR` of the commands that write a directory of results.
#pragma once

#include <filesystem>

namespace brb::cli {

/// `--out` must name a directory that exists or can be created because its parent exists.
/// Checked before the analysis, so that a path that cannot receive the results is an input
/// error (io::InputError) and nothing is written.
void check_output_directory(const std::filesystem::path& directory);

} // namespace brb::cli
