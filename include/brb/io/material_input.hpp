// Material parameter files (p.json) for `brb material`: the steel and mortar schemas of the
// README, read into the material layer's parameter types and checked by the laws
// themselves. Every problem is an InputError naming the file and the JSON path.
#pragma once

#include "brb/io/input_error.hpp"
#include "brb/material/mortar_damage.hpp"
#include "brb/material/parameter_error.hpp"
#include "brb/material/steel_parameters.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace brb::io {

/// Where a set of parameters came from: the file name as the user wrote it and its JSON
/// document, so that a ParameterError can be reported at its JSON path with the value given.
struct ParameterSource {
  std::string file;
  nlohmann::json document;
};

/// The JSON pointer of a parameter key as ParameterError names it:
/// "fy" -> "/fy", "chaboche[1].C" -> "/chaboche/1/C", "voce.Q" -> "/voce/Q".
std::string json_path_of_parameter(std::string_view field);

/// The InputError for a ParameterError raised by parameters read from `source`: located at
/// the parameter's JSON path, with the value found there when the message lacks it.
InputError input_error_from(const ParameterError& error, const ParameterSource& source);

/// Calls `build()` (typically a law's constructor) and reports a ParameterError it throws as
/// an InputError in `source`.
template <class Build>
auto build_checked(const ParameterSource& source, Build&& build) -> decltype(build()) {
  try {
    return std::forward<Build>(build)();
  } catch (const ParameterError& error) {
    throw input_error_from(error, source);
  }
}

/// Steel plasticity-damage parameters (keys E, nu, fy, H_kin, H_iso, optional chaboche, voce,
/// and the damage keys fu, Gf, lc).
struct SteelInput {
  material::SteelParameters parameters;
  /// lc (mm), given with damage (Gf) only.
  std::optional<double> characteristic_length;
  ParameterSource source;

  /// The characteristic length to construct a steel law with: lc, or any positive length
  /// when damage is off (the laws use lc for the softening only).
  double characteristic_length_for_law() const { return characteristic_length.value_or(1.0); }
};

/// Mortar damage parameters (keys E, nu, fc, ft, Gf, lc).
struct MortarInput {
  material::MortarParameters parameters;
  double characteristic_length = 0.0; ///< lc (mm)
  ParameterSource source;
};

class JsonValue;

/// Steel parameters from a JSON object of the steel schema, anywhere in a file (errors carry
/// the object's path). With `characteristic_length` the key lc is read (required with Gf);
/// without it lc is rejected, as in a brace file where each fiber gets lc from its element.
/// Checks the parameter ranges (SteelParameters::validate).
material::SteelParameters read_steel_object(const JsonValue& object,
                                            std::optional<double>* characteristic_length);

/// Parses and checks steel parameters: schema (keys, types), ranges (SteelParameters::validate)
/// and the softening (lc shorter than 2 Gf E / fu^2, LongElementRule::reject).
SteelInput parse_steel_input(std::string_view json_text, const std::string& source);
SteelInput read_steel_input(const std::filesystem::path& file);

/// Parses and checks mortar parameters the same way (MortarParameters::validate, softening with
/// LongElementRule::reject).
MortarInput parse_mortar_input(std::string_view json_text, const std::string& source);
MortarInput read_mortar_input(const std::filesystem::path& file);

} // namespace brb::io
