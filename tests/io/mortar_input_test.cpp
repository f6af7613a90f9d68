// Mortar parameter files: all six keys required, every invalid input an InputError naming
// the file and the JSON path.
#include "brb/io/input_error.hpp"
#include "brb/io/material_input.hpp"
#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <functional>
#include <string>

namespace brb::io {
namespace {

using nlohmann::json;

/// The small-BRB mortar of BRB_SOURCE_FACTS section 6.
json source_mortar() {
  return {{"E", 17520.0}, {"nu", 0.2}, {"fc", 39.92}, {"ft", 3.992}, {"Gf", 0.75}, {"lc", 50.0}};
}

/// lc limit of the exponential softening, 2 Gf E / ft^2, for source_mortar().
double longest_characteristic_length() {
  return 2.0 * 0.75 * 17520.0 / (3.992 * 3.992);
}

TEST(MortarInput, ReadsEveryKeyIntoTheParameters) {
  testing::ScratchDirectory scratch;
  json mortar = source_mortar();
  mortar["units"] = "MPa";
  const auto file = scratch.write("mortar.json", "// grout\n" + mortar.dump(2));

  const MortarInput input = read_mortar_input(file);
  EXPECT_EQ(input.parameters.youngs_modulus, 17520.0);
  EXPECT_EQ(input.parameters.poissons_ratio, 0.2);
  EXPECT_EQ(input.parameters.compressive_strength, 39.92);
  EXPECT_EQ(input.parameters.tensile_strength, 3.992);
  EXPECT_EQ(input.parameters.fracture_energy, 0.75);
  EXPECT_EQ(input.characteristic_length, 50.0);
  EXPECT_EQ(input.source.file, file.string());
}

struct InvalidMortar {
  std::string name;
  std::function<json()> document;
  std::string path;
};

void PrintTo(const InvalidMortar& invalid, std::ostream* out) {
  *out << invalid.name;
}

json with(const std::string& key, json value) {
  json document = source_mortar();
  document[key] = std::move(value);
  return document;
}

json without(const std::string& key) {
  json document = source_mortar();
  document.erase(key);
  return document;
}

class MortarInputRejects : public ::testing::TestWithParam<InvalidMortar> {};

TEST_P(MortarInputRejects, WithFileAndJsonPath) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("mortar.json", GetParam().document().dump());
  try {
    read_mortar_input(file);
    FAIL() << GetParam().name << " was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), file.string());
    EXPECT_EQ(error.location(), GetParam().path);
    const std::string message = error.what();
    EXPECT_NE(message.find(file.string() + ": " + GetParam().path + ": "), std::string::npos)
        << message;
  }
}

INSTANTIATE_TEST_SUITE_P(
    EachInvalidParameter, MortarInputRejects,
    ::testing::Values(
        InvalidMortar{"zero_E", [] { return with("E", 0.0); }, "/E"},
        InvalidMortar{"negative_E", [] { return with("E", -17520.0); }, "/E"},
        InvalidMortar{"nu_at_one_half", [] { return with("nu", 0.5); }, "/nu"},
        InvalidMortar{"nu_below_minus_one", [] { return with("nu", -1.5); }, "/nu"},
        InvalidMortar{"zero_fc", [] { return with("fc", 0.0); }, "/fc"},
        InvalidMortar{"negative_ft", [] { return with("ft", -3.992); }, "/ft"},
        InvalidMortar{"fc_below_ft", [] { return with("fc", 2.0); }, "/fc"},
        InvalidMortar{"negative_Gf", [] { return with("Gf", -0.75); }, "/Gf"},
        InvalidMortar{"zero_lc", [] { return with("lc", 0.0); }, "/lc"},
        InvalidMortar{"lc_too_long_for_softening",
                      [] { return with("lc", 1.5 * longest_characteristic_length()); }, "/lc"},
        InvalidMortar{"missing_E", [] { return without("E"); }, "/E"},
        InvalidMortar{"missing_nu", [] { return without("nu"); }, "/nu"},
        InvalidMortar{"missing_fc", [] { return without("fc"); }, "/fc"},
        InvalidMortar{"missing_ft", [] { return without("ft"); }, "/ft"},
        InvalidMortar{"missing_Gf", [] { return without("Gf"); }, "/Gf"},
        InvalidMortar{"missing_lc", [] { return without("lc"); }, "/lc"},
        InvalidMortar{"unknown_key", [] { return with("fy", 275.0); }, "/fy"},
        InvalidMortar{"ft_as_string", [] { return with("ft", "3.992"); }, "/ft"},
        InvalidMortar{"Gf_as_object",
                      [] {
                        return with("Gf", {{"value", 0.75}});
                      },
                      "/Gf"},
        InvalidMortar{"other_units", [] { return with("units", "psi"); }, "/units"},
        InvalidMortar{"document_is_a_number", [] { return json(17520.0); }, "top level"}),
    [](const ::testing::TestParamInfo<InvalidMortar>& info) { return info.param.name; });

} // namespace
} // namespace brb::io
