// Steel parameter files: the schema of the README, mapped onto SteelParameters, and every
// invalid input reported as an InputError naming the file and the JSON path.
#include "brb/io/input_error.hpp"
#include "brb/io/material_input.hpp"
#include "io/scratch_directory.hpp"

#include "support/invalid_json.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <functional>
#include <string>

namespace brb::io {
namespace {

using nlohmann::json;

json plastic_steel() {
  return {{"E", 210000.0}, {"nu", 0.3}, {"fy", 275.0}, {"H_kin", 1000.0}, {"H_iso", 500.0}};
}

json damaged_steel() {
  json steel = plastic_steel();
  steel["fu"] = 430.0;
  steel["Gf"] = 60.0;
  steel["lc"] = 10.0;
  return steel;
}

/// The longest lc the exponential softening allows (BRB_SOURCE_FACTS section 2: A > 0 needs
/// Gf E / (lc fu^2) > 1/2), from the values of damaged_steel().
double longest_characteristic_length() {
  return 2.0 * 60.0 * 210000.0 / (430.0 * 430.0);
}

TEST(SteelInput, ReadsEveryKeyIntoTheParameters) {
  testing::ScratchDirectory scratch;
  json steel = damaged_steel();
  steel["units"] = "MPa";
  steel["chaboche"] =
      json::array({{{"C", 6000.0}, {"gamma", 60.0}}, {{"C", 1500.0}, {"gamma", 8.0}}});
  steel["voce"] = {{"Q", 40.0}, {"b", 10.0}};
  const auto file = scratch.write("p.json", steel.dump());

  const SteelInput input = read_steel_input(file);
  const auto& parameters = input.parameters;
  EXPECT_EQ(parameters.youngs_modulus, 210000.0);
  EXPECT_EQ(parameters.poissons_ratio, 0.3);
  EXPECT_EQ(parameters.yield_stress, 275.0);
  EXPECT_EQ(parameters.kinematic_hardening, 1000.0);
  EXPECT_EQ(parameters.isotropic_hardening, 500.0);
  ASSERT_EQ(parameters.chaboche.size(), 2u);
  EXPECT_EQ(parameters.chaboche[0].modulus, 6000.0);
  EXPECT_EQ(parameters.chaboche[0].recall, 60.0);
  EXPECT_EQ(parameters.chaboche[1].modulus, 1500.0);
  EXPECT_EQ(parameters.chaboche[1].recall, 8.0);
  EXPECT_EQ(parameters.voce_saturation, 40.0);
  EXPECT_EQ(parameters.voce_rate, 10.0);
  ASSERT_TRUE(parameters.damage.has_value());
  EXPECT_EQ(parameters.damage->onset_stress, 430.0);
  EXPECT_EQ(parameters.damage->fracture_energy, 60.0);
  ASSERT_TRUE(input.characteristic_length.has_value());
  EXPECT_EQ(*input.characteristic_length, 10.0);
  EXPECT_EQ(input.source.file, file.string());
}

TEST(SteelInput, DamageIsOffWithoutFractureEnergy) {
  testing::ScratchDirectory scratch;
  const SteelInput input = read_steel_input(scratch.write("p.json", plastic_steel().dump()));
  EXPECT_FALSE(input.parameters.damage.has_value());
  EXPECT_FALSE(input.characteristic_length.has_value());
  EXPECT_TRUE(input.parameters.chaboche.empty());
  EXPECT_EQ(input.parameters.voce_saturation, 0.0);
}

TEST(SteelInput, AcceptsCommentsAndIntegers) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("p.json", R"(// S275, illustrative
{
  "E": 210000, /* MPa */
  "nu": 0.3,
  "fy": 275,   // MPa
  "H_kin": 0,
  "H_iso": 0
})");
  EXPECT_EQ(read_steel_input(file).parameters.yield_stress, 275.0);
}

TEST(SteelInput, AcceptsCharacteristicLengthJustBelowTheSofteningLimit) {
  testing::ScratchDirectory scratch;
  json steel = damaged_steel();
  steel["lc"] = 0.99 * longest_characteristic_length();
  EXPECT_NO_THROW(read_steel_input(scratch.write("p.json", steel.dump())));
}

TEST(SteelInput, NegativeYieldStressMessageGivesFilePathAndValue) {
  testing::ScratchDirectory scratch;
  json steel = plastic_steel();
  steel["fy"] = -5;
  const auto file = scratch.write("p.json", steel.dump());
  try {
    read_steel_input(file);
    FAIL() << "fy = -5 was accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind(file.string() + ": /fy: ", 0), 0u) << message;
    EXPECT_NE(message.find("-5"), std::string::npos) << message;
  }
}

TEST(SteelInput, SyntaxErrorNamesFileAndLine) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("p.json", "{\"E\": 210000,\n \"nu\": }");
  try {
    read_steel_input(file);
    FAIL() << "malformed JSON was accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    EXPECT_NE(message.find("line 2"), std::string::npos) << message;
  }
}

TEST(SteelInput, MissingFileIsAnInputErrorNamingIt) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.path() / "absent.json";
  try {
    read_steel_input(file);
    FAIL() << "a missing file was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), file.string());
  }
}

TEST(SteelInput, UnknownKeyListsTheAllowedKeys) {
  testing::ScratchDirectory scratch;
  json steel = plastic_steel();
  steel["yield"] = 275.0;
  try {
    read_steel_input(scratch.write("p.json", steel.dump()));
    FAIL() << "an unknown key was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "/yield");
    const std::string message = error.what();
    for (const char* key :
         {"E", "nu", "fy", "H_kin", "H_iso", "chaboche", "voce", "fu", "Gf", "lc", "units"}) {
      EXPECT_NE(message.find(key), std::string::npos) << key << " missing from: " << message;
    }
  }
}

using InvalidSteel = test::InvalidJsonCase;
using test::with;
using test::without;

json with_chaboche(json terms) {
  return with(plastic_steel(), "chaboche", std::move(terms));
}

json term(double modulus, double recall) {
  return {{"C", modulus}, {"gamma", recall}};
}

class SteelInputRejects : public ::testing::TestWithParam<InvalidSteel> {};

TEST_P(SteelInputRejects, WithFileAndJsonPath) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("steel.json", GetParam().document().dump());
  test::expect_rejected_at_path(file, GetParam(), [&] { read_steel_input(file); });
}

INSTANTIATE_TEST_SUITE_P(
    EachInvalidParameter, SteelInputRejects,
    ::testing::Values(
        InvalidSteel{"zero_E", [] { return with(plastic_steel(), "E", 0.0); }, "/E"},
        InvalidSteel{"negative_E", [] { return with(plastic_steel(), "E", -210000.0); }, "/E"},
        InvalidSteel{"nu_at_one_half", [] { return with(plastic_steel(), "nu", 0.5); }, "/nu"},
        InvalidSteel{"nu_above_one_half", [] { return with(plastic_steel(), "nu", 0.7); }, "/nu"},
        InvalidSteel{"nu_at_minus_one", [] { return with(plastic_steel(), "nu", -1.0); }, "/nu"},
        InvalidSteel{"zero_fy", [] { return with(plastic_steel(), "fy", 0.0); }, "/fy"},
        InvalidSteel{"negative_fy", [] { return with(plastic_steel(), "fy", -5.0); }, "/fy"},
        InvalidSteel{"negative_H_kin", [] { return with(plastic_steel(), "H_kin", -1.0); },
                     "/H_kin"},
        InvalidSteel{"negative_H_iso", [] { return with(plastic_steel(), "H_iso", -1.0); },
                     "/H_iso"},
        InvalidSteel{"fu_below_fy", [] { return with(damaged_steel(), "fu", 200.0); }, "/fu"},
        InvalidSteel{"negative_Gf", [] { return with(damaged_steel(), "Gf", -60.0); }, "/Gf"},
        InvalidSteel{"zero_Gf", [] { return with(damaged_steel(), "Gf", 0.0); }, "/Gf"},
        InvalidSteel{"zero_lc", [] { return with(damaged_steel(), "lc", 0.0); }, "/lc"},
        InvalidSteel{
            "lc_too_long_for_softening",
            [] { return with(damaged_steel(), "lc", 2.0 * longest_characteristic_length()); },
            "/lc"},
        InvalidSteel{"lc_at_softening_limit",
                     [] { return with(damaged_steel(), "lc", longest_characteristic_length()); },
                     "/lc"},
        InvalidSteel{"missing_E", [] { return without(plastic_steel(), "E"); }, "/E"},
        InvalidSteel{"missing_nu", [] { return without(plastic_steel(), "nu"); }, "/nu"},
        InvalidSteel{"missing_fy", [] { return without(plastic_steel(), "fy"); }, "/fy"},
        InvalidSteel{"missing_H_kin", [] { return without(plastic_steel(), "H_kin"); }, "/H_kin"},
        InvalidSteel{"missing_H_iso", [] { return without(plastic_steel(), "H_iso"); }, "/H_iso"},
        InvalidSteel{"Gf_without_fu", [] { return without(damaged_steel(), "fu"); }, "/fu"},
        InvalidSteel{"Gf_without_lc", [] { return without(damaged_steel(), "lc"); }, "/lc"},
        InvalidSteel{"fu_without_Gf", [] { return without(damaged_steel(), "Gf"); }, "/fu"},
        InvalidSteel{"lc_without_Gf", [] { return with(plastic_steel(), "lc", 10.0); }, "/lc"},
        InvalidSteel{"unknown_key", [] { return with(plastic_steel(), "Fy", 275.0); }, "/Fy"},
        InvalidSteel{"five_chaboche_terms",
                     [] {
                       return with_chaboche(
                           json::array({term(1000, 10), term(1000, 10), term(1000, 10),
                                        term(1000, 10), term(1000, 10)}));
                     },
                     "/chaboche"},
        InvalidSteel{"chaboche_not_an_array", [] { return with_chaboche(term(1000, 10)); },
                     "/chaboche"},
        InvalidSteel{"chaboche_negative_C",
                     [] {
                       return with_chaboche(json::array({term(1000, 10), term(-1000, 10)}));
                     },
                     "/chaboche/1/C"},
        InvalidSteel{"chaboche_negative_gamma",
                     [] { return with_chaboche(json::array({term(1000, -10)})); },
                     "/chaboche/0/gamma"},
        InvalidSteel{"chaboche_missing_gamma",
                     [] {
                       return with_chaboche(json::array({{{"C", 1000.0}}}));
                     },
                     "/chaboche/0/gamma"},
        InvalidSteel{"chaboche_unknown_key",
                     [] {
                       return with_chaboche(
                           json::array({term(1000, 10), {{"C", 1.0}, {"gamma", 1.0}, {"b", 1.0}}}));
                     },
                     "/chaboche/1/b"},
        InvalidSteel{"chaboche_term_not_an_object",
                     [] { return with_chaboche(json::array({1000.0})); }, "/chaboche/0"},
        InvalidSteel{"voce_negative_Q",
                     [] {
                       return with(plastic_steel(), "voce", {{"Q", -40.0}, {"b", 10.0}});
                     },
                     "/voce/Q"},
        InvalidSteel{"voce_negative_b",
                     [] {
                       return with(plastic_steel(), "voce", {{"Q", 40.0}, {"b", -10.0}});
                     },
                     "/voce/b"},
        InvalidSteel{"voce_missing_b",
                     [] {
                       return with(plastic_steel(), "voce", {{"Q", 40.0}});
                     },
                     "/voce/b"},
        InvalidSteel{
            "voce_unknown_key",
            [] {
              return with(plastic_steel(), "voce", {{"Q", 40.0}, {"b", 10.0}, {"Q_inf", 1.0}});
            },
            "/voce/Q_inf"},
        InvalidSteel{"voce_not_an_object", [] { return with(plastic_steel(), "voce", 40.0); },
                     "/voce"},
        InvalidSteel{"E_as_string", [] { return with(plastic_steel(), "E", "210000"); }, "/E"},
        InvalidSteel{"nu_as_boolean", [] { return with(plastic_steel(), "nu", true); }, "/nu"},
        InvalidSteel{"fy_null", [] { return with(plastic_steel(), "fy", nullptr); }, "/fy"},
        InvalidSteel{"H_kin_as_array",
                     [] { return with(plastic_steel(), "H_kin", json::array({1.0})); }, "/H_kin"},
        InvalidSteel{"other_units", [] { return with(plastic_steel(), "units", "kN-m"); },
                     "/units"},
        InvalidSteel{"units_as_number", [] { return with(plastic_steel(), "units", 1.0); },
                     "/units"},
        InvalidSteel{"document_is_an_array", [] { return json::array({plastic_steel()}); },
                     "top level"}),
    [](const ::testing::TestParamInfo<InvalidSteel>& info) { return info.param.name; });

} // namespace
} // namespace brb::io
