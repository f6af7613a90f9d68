#include "brb/analysis/material_driver.hpp"

#include <array>
#include <charconv>
#include <string>

namespace brb::analysis {
namespace {

std::string shortest_text(double value) {
  std::array<char, 32> buffer{};
  const auto end = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value).ptr;
  return std::string(buffer.data(), end);
}

} // namespace

MaterialPathFailure::MaterialPathFailure(std::size_t row, double strain, int substeps)
    : std::runtime_error("the material point could not follow the increment to strain " +
                         shortest_text(strain) + " (history row " + std::to_string(row + 1) +
                         ") even in " + std::to_string(substeps) +
                         " substeps: no converged, finite response"),
      row_(row), strain_(strain), substeps_(substeps) {}

MaterialPathResult drive_strain_path(const UniaxialMaterialPoint& point,
                                     std::span<const double> strains,
                                     const SubsteppingPolicy& policy) {
  return std::visit([&](const auto& law) { return drive_strain_path_of(law, strains, policy); },
                    point);
}

} // namespace brb::analysis
