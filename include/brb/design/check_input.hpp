// Check files (README "brb check"): JSON with comments, read into a CheckSpec. Every problem
// is an io::InputError naming the file, the JSON path and what was expected (e.g. a negative
// drift, Ry < 1, an unknown edition, a brace id that is not a brb element of the frame).
// Paths inside the file (brace, frame model) are relative to the check file's folder.
#pragma once

#include "brb/design/check_spec.hpp"

#include <filesystem>
#include <string>
#include <string_view>

namespace brb::design {

/// Parses a check file's text; `source` names it in errors, paths are relative to
/// `base_directory`.
CheckSpec parse_check(std::string_view json_text, const std::string& source,
                      const std::filesystem::path& base_directory);

/// read_text_file + parse_check with the file's folder as the base directory; the check's
/// default name is the file's stem.
CheckSpec read_check(const std::filesystem::path& file);

} // namespace brb::design
