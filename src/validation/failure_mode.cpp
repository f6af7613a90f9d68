#include "brb/validation/failure_mode.hpp"

#include <array>
#include <cstdlib>
#include <utility>

namespace brb::validation {
namespace {

constexpr std::array<std::pair<FailureMode, std::string_view>, 4> kNames{
    {{FailureMode::none, "none"},
     {FailureMode::core_fracture, "core_fracture"},
     {FailureMode::casing_failure, "casing_failure"},
     {FailureMode::global_buckling, "global_buckling"}}};

/// The first raised flag of `indicators` in the tie order of model_failure.
FailureMode raised_mode(const analysis::BraceIndicators& indicators) {
  if (indicators.core_fracture)
    return FailureMode::core_fracture;
  if (indicators.casing_failure)
    return FailureMode::casing_failure;
  if (indicators.global_buckling)
    return FailureMode::global_buckling;
  return FailureMode::none;
}

std::string described(std::string_view who, const FailureEvent& event) {
  std::string text = std::string(who) + " " + std::string(to_string(event.mode));
  if (event.mode != FailureMode::none)
    text += " in cycle " + std::to_string(event.cycle);
  return text;
}

} // namespace

std::string_view to_string(FailureMode mode) {
  for (const auto& [known, name] : kNames) {
    if (known == mode)
      return name;
  }
  return "none";
}

std::optional<FailureMode> failure_mode_named(std::string_view name) {
  for (const auto& [mode, known] : kNames) {
    if (known == name)
      return mode;
  }
  return std::nullopt;
}

std::string failure_mode_names() {
  std::string names;
  for (const auto& [mode, name] : kNames)
    names += (names.empty() ? "\"" : ", \"") + std::string(name) + "\"";
  return names;
}

std::optional<FailureEvent> model_failure(const analysis::CyclicTestResult& result) {
  if (raised_mode(result.indicators) == FailureMode::none)
    return FailureEvent{};
  // The flags are running ("once raised, stays raised"): the first history point with one
  // raised is the step of the failure; its cycle is that step's row of the hysteresis.
  for (const analysis::ElementHistoryPoint& point : result.history) {
    const FailureMode mode = raised_mode(point.indicators);
    if (mode == FailureMode::none)
      continue;
    for (const analysis::CyclicStep& step : result.steps) {
      if (step.step == point.step)
        return FailureEvent{mode, step.cycle};
    }
    return std::nullopt;
  }
  return std::nullopt;
}

FailureComparison compare_failures(const FailureEvent& model, const FailureEvent& reference,
                                   int cycle_tolerance) {
  FailureComparison comparison;
  comparison.description = described("model", model) + ", " + described("reference", reference);
  comparison.agrees =
      model.mode == reference.mode && (model.mode == FailureMode::none ||
                                       std::abs(model.cycle - reference.cycle) <= cycle_tolerance);
  return comparison;
}

} // namespace brb::validation
