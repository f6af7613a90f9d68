#include "brb/io/material_input.hpp"

#include "brb/io/json_input.hpp"
#include "brb/material/steel_uniaxial.hpp"

#include <cstddef>
#include <string>

namespace brb::io {
namespace {

using material::LongElementRule;

constexpr std::string_view kUnitSystem = "MPa";

/// The optional "units" key: only the project's unit system (N, mm, s, MPa, tonne) for now.
void check_units(const JsonValue& root) {
  const auto units = root.find("units");
  if (!units)
    return;
  const std::string value = units->string("unit system, \"MPa\" for N, mm, s, MPa, tonne");
  if (value != kUnitSystem) {
    throw units->error("unsupported unit system \"" + value +
                       "\"; expected \"MPa\" (N, mm, s, MPa, tonne)");
  }
}

std::vector<material::BackStressTerm> read_chaboche_terms(const JsonValue& chaboche) {
  const std::size_t count = chaboche.expect_array(material::SteelParameters::kMaxChabocheTerms,
                                                  "Chaboche back-stress terms {\"C\", \"gamma\"}");
  std::vector<material::BackStressTerm> terms;
  terms.reserve(count);
  for (std::size_t index = 0; index < count; ++index) {
    const JsonValue term = chaboche.element(index);
    term.expect_object({"C", "gamma"}, "an object {\"C\": MPa, \"gamma\": -}");
    terms.push_back({
        .modulus = term.at("C", "back-stress modulus C, MPa").number("back-stress modulus C, MPa"),
        .recall = term.at("gamma", "recall rate gamma, -").number("recall rate gamma, -"),
    });
  }
  return terms;
}

double required_number(const JsonValue& object, std::string_view key, std::string_view meaning) {
  return object.at(key, meaning).number(meaning);
}

} // namespace

std::string json_path_of_parameter(std::string_view field) {
  if (field.empty())
    return {};
  std::string path = "/";
  for (const char character : field) {
    if (character == '[' || character == '.') {
      path += '/';
    } else if (character != ']') {
      path += character;
    }
  }
  return path;
}

InputError input_error_from(const ParameterError& error, const ParameterSource& source) {
  const std::string path = json_path_of_parameter(error.field());
  std::string expected = error.what();
  if (expected.find("got") == std::string::npos && !path.empty()) {
    try {
      const nlohmann::json::json_pointer pointer(path);
      if (source.document.contains(pointer)) {
        expected += " (got " + describe_json_value(source.document.at(pointer)) + ")";
      }
    } catch (const nlohmann::json::exception&) {
      // A field name that is not a valid pointer: report the message as it is.
    }
  }
  return InputError(source.file, path.empty() ? "top level" : path, expected);
}

material::SteelParameters read_steel_object(const JsonValue& object,
                                            std::optional<double>* characteristic_length) {
  if (characteristic_length) {
    object.expect_object(
        {"units", "E", "nu", "fy", "H_kin", "H_iso", "chaboche", "voce", "fu", "Gf", "lc"},
        "an object of steel parameters");
  } else {
    object.expect_object(
        {"units", "E", "nu", "fy", "H_kin", "H_iso", "chaboche", "voce", "fu", "Gf"},
        "an object of steel parameters (lc comes from the element)");
  }
  check_units(object);

  material::SteelParameters parameters;
  parameters.youngs_modulus = required_number(object, "E", "Young's modulus E, MPa");
  parameters.poissons_ratio = required_number(object, "nu", "Poisson's ratio nu");
  parameters.yield_stress = required_number(object, "fy", "yield stress fy, MPa");
  parameters.kinematic_hardening =
      required_number(object, "H_kin", "linear kinematic hardening modulus H_kin, MPa");
  parameters.isotropic_hardening =
      required_number(object, "H_iso", "linear isotropic hardening modulus H_iso, MPa");

  if (const auto chaboche = object.find("chaboche")) {
    parameters.chaboche = read_chaboche_terms(*chaboche);
  }
  if (const auto voce = object.find("voce")) {
    voce->expect_object({"Q", "b"}, "an object {\"Q\": MPa, \"b\": -}");
    parameters.voce_saturation = required_number(*voce, "Q", "Voce saturation stress Q, MPa");
    parameters.voce_rate = required_number(*voce, "b", "Voce rate b, -");
  }

  // Damage is on exactly when Gf is given; fu (and lc, in a material file) belong to it.
  if (object.find("Gf")) {
    parameters.damage = material::SteelDamageParameters{
        .onset_stress =
            required_number(object, "fu", "damage onset stress fu, MPa; required when Gf is given"),
        .fracture_energy = required_number(object, "Gf", "fracture energy Gf, N/mm"),
    };
    if (characteristic_length) {
      *characteristic_length =
          required_number(object, "lc", "characteristic length lc, mm; required when Gf is given");
    }
  } else {
    for (const std::string_view damage_key : {"fu", "lc"}) {
      if (const auto orphan = object.find(damage_key)) {
        throw orphan->error(std::string(damage_key) +
                            " is used only by damage: give Gf (fracture energy, N/mm) too, or "
                            "remove " +
                            std::string(damage_key));
      }
    }
  }

  // The parameter ranges (the softening is checked where lc is known).
  try {
    parameters.validate();
  } catch (const ParameterError& error) {
    throw InputError(object.source(), object.path() + json_path_of_parameter(error.field()),
                     error.what());
  }
  return parameters;
}

SteelInput parse_steel_input(std::string_view json_text, const std::string& source) {
  SteelInput input;
  input.source = ParameterSource{source, parse_json(json_text, source)};
  const JsonValue root(input.source.document, source);
  input.parameters = read_steel_object(root, &input.characteristic_length);

  // The law's own checks: lc short enough for the softening.
  build_checked(input.source, [&input] {
    return material::SteelUniaxial(input.parameters, input.characteristic_length_for_law(),
                                   LongElementRule::reject);
  });
  return input;
}

SteelInput read_steel_input(const std::filesystem::path& file) {
  return parse_steel_input(read_text_file(file), file.string());
}

MortarInput parse_mortar_input(std::string_view json_text, const std::string& source) {
  MortarInput input;
  input.source = ParameterSource{source, parse_json(json_text, source)};
  const JsonValue root(input.source.document, source);
  root.expect_object({"units", "E", "nu", "fc", "ft", "Gf", "lc"},
                     "an object of mortar parameters");
  check_units(root);

  auto& parameters = input.parameters;
  parameters.youngs_modulus = required_number(root, "E", "Young's modulus E, MPa");
  parameters.poissons_ratio = required_number(root, "nu", "Poisson's ratio nu");
  parameters.compressive_strength = required_number(root, "fc", "compressive strength fc, MPa");
  parameters.tensile_strength = required_number(root, "ft", "tensile strength ft, MPa");
  parameters.fracture_energy = required_number(root, "Gf", "fracture energy Gf, N/mm");
  input.characteristic_length = required_number(root, "lc", "characteristic length lc, mm");

  build_checked(input.source, [&input] {
    return material::MortarUniaxial(input.parameters, input.characteristic_length,
                                    LongElementRule::reject);
  });
  return input;
}

MortarInput read_mortar_input(const std::filesystem::path& file) {
  return parse_mortar_input(read_text_file(file), file.string());
}

} // namespace brb::io
