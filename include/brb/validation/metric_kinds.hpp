// The registry of metric kinds of metrics.json (validation/README.md): one entry per kind,
// each with the parameters it reads, a check of them at their JSON paths and the function
// that turns a cyclic test into the metric's value. To add a kind: write its two functions in
// metric_kinds.cpp and list it in metric_kinds().
#pragma once

#include "brb/analysis/cyclic_test.hpp"
#include "brb/io/json_input.hpp"
#include "brb/validation/failure_mode.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace brb::validation {

/// A reference (a lab record, a `brb solid` run or an external solver's export) matched to
/// the protocol's points (specimens with a reference): the reference force at protocol point
/// k (NaN where the point is not compared), the comparison's settings and the failure the
/// reference states.
struct RecordSeries {
  std::vector<double> deformation; ///< mm, the protocol's points
  std::vector<double> test_force;  ///< N, per point; NaN: not compared
  double reversal_threshold = 0.0; ///< mm
  double energy_floor_fraction = 0.05;
  std::optional<FailureEvent> failure; ///< for record_failure_mode
};

/// What a metric is evaluated on: one cyclic test of one specimen at one refinement. The
/// kinds read the hysteresis (result.steps) and the indicators only (and, for the failure
/// cycle, result.history), so that they apply to any force-deformation record.
struct RunData {
  const analysis::CyclicTestResult& result;
  double yield_deformation = 0.0;       ///< dy of the brace model, mm
  double yield_force = 0.0;             ///< Py = fy A_core, N
  double yielding_length = 0.0;         ///< mm, of the core
  const RecordSeries* record = nullptr; ///< for the record_* kinds
};

/// A metric's value, or why there is none (e.g. the cycle asked for was not reached).
struct MetricValue {
  std::optional<double> value;
  std::string note; ///< which cycle or point the value comes from, or why there is none
};

struct MetricKind {
  std::string_view name;
  std::string_view meaning; ///< one line for the README and error messages
  /// Keys of the metric object the kind reads, beyond the common ones (name, kind, reference,
  /// tolerance, at_least, at_most, unit, source, note).
  std::vector<std::string_view> keys;
  bool is_flag = false; ///< value 1 (true) or 0 (false), checked against "expected"
  /// Checks the kind's parameters in `metric` (an object), throwing io::InputError at the
  /// parameter's JSON path.
  void (*check)(const io::JsonValue& metric);
  /// The value of the metric on a run (parameters already checked).
  MetricValue (*evaluate)(const nlohmann::json& metric, const RunData& run);
};

/// Every kind, in the order the README lists them.
std::span<const MetricKind> metric_kinds();

/// The kind called `name`, or nullptr.
const MetricKind* find_metric_kind(std::string_view name);

/// The names of every kind, "a, b, c" (for error messages).
std::string metric_kind_names();

} // namespace brb::validation
