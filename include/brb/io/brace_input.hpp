// Brace files (the `brb` brace schema, README "Brace files"): JSON with comments, read into
// a model::BraceSpec. Every problem is an InputError naming the file, the JSON path and
// what was expected.
#pragma once

#include "brb/io/json_input.hpp"
#include "brb/model/brace_spec.hpp"

#include <filesystem>
#include <string>
#include <string_view>

namespace brb::io {

model::BraceSpec parse_brace(std::string_view json_text, const std::string& source);
model::BraceSpec read_brace(const std::filesystem::path& file);

/// The mortar fields E, nu, fc, ft, Gf of a JSON object (its other keys are the caller's to
/// check), validated; errors at their JSON paths. Shared by brace and frame files.
material::MortarParameters read_mortar_fields(const JsonValue& object);

} // namespace brb::io
