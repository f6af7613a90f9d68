// Builds the FrameModel of a frame file's FrameSpec: nodes, supports, masses, constraints,
// elements (frame elements, fiber beams, BRBs at their fidelity, `auto` resolved by
// model/brace_fidelity.hpp), the gravity load vector, stories and floors.
#pragma once

#include "brb/frame/frame_model.hpp"
#include "brb/model/frame_spec.hpp"

#include <string>

namespace brb::frame {

/// `source` names the model file in errors: an element the element layer rejects raises an
/// io::InputError at "/elements/<index>" with the element's message.
FrameModel build_frame(const model::FrameSpec& spec, const std::string& source);

} // namespace brb::frame
