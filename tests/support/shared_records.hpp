// The PEER AT2 records of the shared data (../shared/data/ground_motions, SOURCES.md), sorted
// by name: the records the frame tests run.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

namespace brb::test {

inline std::filesystem::path shared_ground_motions() {
  return std::filesystem::path(BRB_SHARED_DIR) / "data" / "ground_motions";
}

inline std::vector<std::filesystem::path> shared_at2_records() {
  std::vector<std::filesystem::path> records;
  for (const auto& entry : std::filesystem::directory_iterator(shared_ground_motions())) {
    std::string extension = entry.path().extension().string();
    for (char& c : extension)
      c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".at2")
      records.push_back(entry.path());
  }
  std::sort(records.begin(), records.end());
  return records;
}

} // namespace brb::test
