#include "output_directory.hpp"

#include "brb/io/input_error.hpp"

namespace brb::cli {

namespace fs = std::filesystem;

void check_output_directory(const fs::path& directory) {
  const std::string name = directory.string();
  if (directory.empty())
    throw io::InputError("--out", "", "must name a directory");
  if (fs::exists(directory)) {
    if (!fs::is_directory(directory))
      throw io::InputError(name, "", "--out must name a directory, and this is not one");
    return;
  }
  // "out/" names the directory "out": drop the trailing separator before taking the parent.
  const fs::path target = directory.has_filename() ? directory : directory.parent_path();
  const fs::path parent = target.parent_path();
  if (!parent.empty() && !fs::is_directory(parent)) {
    throw io::InputError(name, "",
                         "cannot create the output directory: its parent '" + parent.string() +
                             "' does not exist");
  }
}

} // namespace brb::cli
