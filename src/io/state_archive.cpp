#include "brb/io/state_archive.hpp"
#include "brb/io/input_error.hpp"

#include <fstream>
#include <iterator>

namespace brb::io {

std::string file_fingerprint(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw InputError(file.string(), "", "cannot be read (for the checkpoint's run key)");
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return fingerprint(bytes);
}

} // namespace brb::io
