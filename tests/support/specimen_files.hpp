// Files of the validation specimens (validation/<id>/, validation/README.md) that tests read.
#pragma once

#include <filesystem>
#include <string_view>

namespace brb::test {

/// validation/<id>/brace.json in the source tree.
inline std::filesystem::path specimen_brace(std::string_view id) {
  return std::filesystem::path(BRB_SOURCE_DIR) / "validation" / id / "brace.json";
}

} // namespace brb::test
