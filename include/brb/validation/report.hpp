// The validation report: REPORT.md for people and report.json for programs, generated from
// the outcomes of every run of every specimen and the contrasts (README "brb validate").
#pragma once

#include "brb/validation/contrast.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace brb::validation {

struct ValidationReport {
  std::string validation_directory; ///< as the user gave it
  std::string invocation; ///< the command that made the report, e.g. "brb validate validation"
  std::vector<SpecimenOutcome> specimens;
  std::vector<ContrastResult> contrasts;
};

/// Checks passed and failed (runs and contrasts), and values only reported.
struct Tally {
  int passed = 0;
  int failed = 0;
  int reported = 0;
  bool all_passed() const { return failed == 0; }
};

Tally tally(const ValidationReport& report);

/// REPORT.md: the summary line first, an overview table, then per specimen and refinement the
/// table metric | reference | result | error | tolerance | pass | where, with the run's time,
/// steps, energy-balance error and completion; then the contrasts.
std::string report_markdown(const ValidationReport& report);

/// report.json: the same content, numbers at full precision.
nlohmann::ordered_json report_json(const ValidationReport& report);

} // namespace brb::validation
