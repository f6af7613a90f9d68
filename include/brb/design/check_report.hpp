// The outputs of `brb check` (README "brb check"): check.json (every value, criterion and the
// verdict) and check.md (a table an engineer can attach to a calculation). The qualification
// hysteresis is io::hysteresis_table of the test.
#pragma once

#include "brb/design/check.hpp"
#include "brb/design/check_spec.hpp"

#include <nlohmann/json.hpp>
#include <string>

namespace brb::design {

/// check.json (keys in the README).
nlohmann::ordered_json check_json(const CheckSpec& check, const CheckResult& result);

/// check.md: inputs, demand, per-cycle table, criteria with value and limit, verdict.
std::string check_markdown(const CheckSpec& check, const CheckResult& result);

/// "PASS" or "FAIL".
std::string verdict(const CheckResult& result);

} // namespace brb::design
