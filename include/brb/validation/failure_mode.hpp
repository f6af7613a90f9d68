// The failure mode of a brace and the cycle it happens in (issue 6, item 6): what a reference
// (a test, a `brb solid` run, an external 3D solver) states in metrics.json, what the model
// shows through its element flags (summary.json's `element` block: core_fracture,
// casing_failure, global_buckling), and whether the two agree within a number of cycles.
#pragma once

#include "brb/analysis/cyclic_test.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace brb::validation {

enum class FailureMode { none, core_fracture, casing_failure, global_buckling };

/// "none", "core_fracture", "casing_failure", "global_buckling" (summary.json's flag names).
std::string_view to_string(FailureMode mode);
/// The mode of that name, or nothing.
std::optional<FailureMode> failure_mode_named(std::string_view name);
/// The names of every mode, for error messages: "\"none\", \"core_fracture\", ...".
std::string failure_mode_names();

/// A failure and the protocol cycle it happened in (1-based; the `cycle` column of
/// hysteresis.csv). Without a failure (mode none) the cycle is 0.
struct FailureEvent {
  FailureMode mode = FailureMode::none;
  int cycle = 0;
};

/// The model's failure: the first of its flags to be raised, in the cycle of the step where it
/// was (ties at one step in the order core_fracture, casing_failure, global_buckling); mode
/// none when no flag was raised. The step needs result.history (run_cyclic_test asked to
/// record it): with a raised flag and no history there is nothing (the cycle is unknown).
std::optional<FailureEvent> model_failure(const analysis::CyclicTestResult& result);

/// Whether the model's failure agrees with the reference's: the same mode and, when it is not
/// none, cycles at most `cycle_tolerance` apart. `description` says both, e.g.
/// "model casing_failure in cycle 4, reference casing_failure in cycle 3".
struct FailureComparison {
  bool agrees = false;
  std::string description;
};

FailureComparison compare_failures(const FailureEvent& model, const FailureEvent& reference,
                                   int cycle_tolerance);

} // namespace brb::validation
