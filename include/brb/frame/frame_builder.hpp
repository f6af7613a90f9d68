// Builds the FrameModel of a frame file's FrameSpec: nodes, supports, masses, constraints,
// elements (frame elements, fiber beams, BRBs at their fidelity, `auto` resolved by
// model/brace_fidelity.hpp), the gravity load vector, stories and floors.
#pragma once

#include "brb/frame/frame_model.hpp"
#include "brb/frame/frame_run.hpp"
#include "brb/model/frame_spec.hpp"
#include "brb/model/work_skips.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace brb::frame {

/// How every brace of the model is built, overriding the file's fidelities: for comparisons
/// (the benchmark) and quick studies. `elastic`: an elastic truss of the brace's series
/// axial stiffness (a frame that never yields in its braces).
enum class BraceOverride { none, elastic, truss, full, automatic };

/// The override named `text` ("elastic", "truss", "full", "auto"); nothing for another text.
std::optional<BraceOverride> brace_override_named(std::string_view text);
/// "elastic", "truss", "full", "auto"; "none" for none (the model's own fidelities).
std::string_view brace_override_name(BraceOverride braces);

/// `source` names the model file in errors: an element the element layer rejects raises an
/// io::InputError at "/elements/<index>" with the element's message. `skips`: the work skips
/// of the elements and of `auto` (WorkSkips; the recorders' one is FrameRunOptions::skips).
FrameModel build_frame(const model::FrameSpec& spec, const std::string& source,
                       BraceOverride braces = BraceOverride::none,
                       const model::WorkSkips& skips = {});

/// The run options a frame file gives (integrator, step, damping, recorders, ground-motion
/// directions). Brace histories: the ids listed; "all" is resolved against the built frame
/// by the caller (FrameModel::braces).
FrameRunOptions run_options_of(const model::FrameSpec& spec);

} // namespace brb::frame
