#include "brb/design/edition.hpp"

#include <array>
#include <utility>

namespace brb::design {
namespace {

constexpr std::array<std::pair<Edition, std::string_view>, 4> kEditions{{
    {Edition::aisc341_05, "341-05"},
    {Edition::aisc341_10, "341-10"},
    {Edition::aisc341_16, "341-16"},
    {Edition::aisc341_22, "341-22"},
}};

} // namespace

std::string to_string(Edition edition) {
  for (const auto& [known, name] : kEditions) {
    if (known == edition)
      return std::string(name);
  }
  return "unknown";
}

std::optional<Edition> edition_from_string(std::string_view name) {
  for (const auto& [known, known_name] : kEditions) {
    if (known_name == name)
      return known;
  }
  return std::nullopt;
}

std::vector<std::string> edition_names() {
  std::vector<std::string> names;
  for (const auto& entry : kEditions)
    names.emplace_back(entry.second);
  return names;
}

EditionParameters edition_parameters(Edition edition) {
  EditionParameters parameters;
  parameters.edition = edition;
  // The loading sequence (K3.4c / appendix T), the 200 Delta_by target, the 1 % minimum
  // drift, the 2.0 x design drift range of beta and omega and the 1.0 Pysc strength
  // criterion are the same in every edition listed (AISC341_NOTES.md).
  parameters.source = "AISC341_NOTES.md (paraphrase of ANSI/AISC 341-16 F4.2a, K3.4c, K3.8; "
                      "ASCE/SEI 7-16)";
  switch (edition) {
  case Edition::aisc341_05:
    parameters.beta_limit = 1.3;
    parameters.beta_limit_source = "AISC 341-05 appendix T (AISC341_NOTES.md, K3.8 d)";
    break;
  case Edition::aisc341_10:
  case Edition::aisc341_16:
  case Edition::aisc341_22:
    // The notes give 1.3 for the 2005 edition only and ask to check later editions; their
    // text was not available here, so the notes' value is kept and said to be so. A check
    // file's "beta_limit" overrides it.
    parameters.beta_limit = 1.3;
    parameters.beta_limit_source =
        "the notes' value (AISC341_NOTES.md: 1.3, 2005 edition); not verified against the "
        "text of " +
        to_string(edition) + ": set \"beta_limit\" in the check file to override";
    break;
  }
  return parameters;
}

} // namespace brb::design
