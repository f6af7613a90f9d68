// Frame model files (README "Frame model files"): JSON with comments, read into a
// model::FrameSpec. Every problem is an InputError naming the file, the JSON path and what
// was expected: schema (keys, types, ranges), duplicate ids, references to undefined nodes,
// sections, materials or elements, zero-length members, brace files (missing or invalid,
// or whose length differs from the distance between the brace's nodes by more than 1 mm),
// a model without mass, stories whose top is not above their bottom.
#pragma once

#include "brb/model/frame_spec.hpp"

#include <filesystem>
#include <string>
#include <string_view>

namespace brb::io {

/// The largest difference (mm) accepted between a brace's total length (connections +
/// transitions at both ends + yielding length) and the distance between its nodes.
inline constexpr double kBraceLengthTolerance = 1.0;

/// Parses a frame model; `source` names it in errors, brace file paths are relative to
/// `base_directory` (the folder of the model file).
model::FrameSpec parse_frame(std::string_view json_text, const std::string& source,
                             const std::filesystem::path& base_directory);

/// read_text_file + parse_frame with the file's folder as the base directory.
model::FrameSpec read_frame(const std::filesystem::path& file);

} // namespace brb::io
