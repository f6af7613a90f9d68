// The numerical stress suite (issue 9): what one stress case runs. A case is either a brace
// driven through a deformation history (the virtual cyclic test of `brb cyclic`, at `truss`
// or `full` fidelity) or a frame under a scaled ground motion (`brb frame`). Cases are plain
// values built by the deterministic generators of stress_generators.hpp: the same seed gives
// the same case, bit for bit.
#pragma once

#include "brb/analysis/static_analysis.hpp"
#include "brb/frame/frame_builder.hpp"
#include "brb/model/brace_spec.hpp"
#include "brb/model/frame_spec.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace brb::study {

/// The case groups of the issue, one table each in the report.
enum class StressGroup {
  random_history,        ///< random reversals, amplitudes up to 20 dy
  monotonic_compression, ///< straight to 10 % core strain in compression
  step_size,             ///< one protocol at step sizes 1/100 .. 10 x the default
  frame_collapse,        ///< a frame at (and beyond) its collapse intensity
  near_singular          ///< gap 1e-6 mm, friction 1.0, casing barely stiff enough
};

/// "random_history", "monotonic_compression", "step_size", "frame_collapse", "near_singular".
std::string_view group_name(StressGroup group);
/// Every group, in report order.
const std::vector<StressGroup>& all_stress_groups();

/// A brace (its fidelity in spec.element.fidelity: truss, or full run as the expanded model
/// as `brb cyclic` does) driven through `deformation` (mm, first point 0, one analysis step
/// per further point) under displacement control of its end node.
struct BraceStress {
  model::BraceSpec brace;
  std::vector<double> deformation;
  analysis::NewtonSettings settings;
};

/// A frame (built with every brace at `braces`) under `acceleration` (mm/s^2, sampled at
/// `dt`, already scaled by `scale`) along the model's first ground-motion direction, at the
/// model's own analysis settings; all recorders on, so that every output is checked.
struct FrameStress {
  model::FrameSpec frame;
  std::string source; ///< the model file, for messages
  frame::BraceOverride braces = frame::BraceOverride::truss;
  std::string record; ///< the record's name
  double scale = 1.0; ///< factor on the record (already applied)
  double dt = 0.0;    ///< s, record sampling
  std::vector<double> acceleration;
  /// Story drift ratio that stops the run (a collapse); default: the model's. The cases
  /// "beyond collapse" raise it so that the solver is driven on past 10 % drift.
  std::optional<double> drift_limit;
};

struct StressCase {
  std::string name; ///< unique within a suite, e.g. "random_history/truss/seed-3"
  StressGroup group = StressGroup::random_history;
  /// How the case was generated, with its parameters (for the report).
  std::string generator;
  std::uint64_t seed = 0; ///< of the generator (0 for deterministic generators)
  /// The settings that differ from the defaults, in words (e.g. "max step 0.01 x default").
  std::string settings;
  std::variant<BraceStress, FrameStress> subject;
};

} // namespace brb::study
