// One run of an IDA: a record scaled to an intensity, and the demands it produced. It is the
// unit of the journal (one JSON line per run) and of ida_points.csv.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace brb::ida {

/// Why a run counts as collapse (Vamvatsikos & Cornell 2002: the flatline). Numerical
/// collapse (a step failed after every fallback) is recorded as such, never as a drift.
enum class CollapseKind { none, drift_limit, numerical };

std::string_view collapse_kind_name(CollapseKind kind); ///< "none", "drift", "numerical"

struct IdaPoint {
  int record = 0;          ///< index in the suite
  std::string record_name; ///< the suite's name of the record
  double intensity = 0.0;  ///< IM asked (g)
  double scale = 0.0;      ///< factor on the (normalised) record that gives it
  CollapseKind collapse = CollapseKind::none;
  bool converged = true;                ///< every step converged (possibly with fallbacks)
  std::vector<double> max_drift;        ///< per story, peak |drift ratio|
  std::vector<double> residual_drift;   ///< per story, |drift ratio| at the end
  double peak_floor_acceleration = 0.0; ///< g, absolute, over all floors
  double max_core_strain = 0.0;         ///< over all braces
  double max_cid = 0.0;                 ///< cumulative inelastic deformation, multiples of dy
  double end_time = 0.0;                ///< s reached
  int fallbacks = 0;                    ///< solver fallbacks used
  double run_time = 0.0;                ///< s, wall clock (the one non-deterministic field)
  std::string stop_reason;

  bool collapsed() const { return collapse != CollapseKind::none; }
  double peak_drift() const;    ///< max over stories
  double peak_residual() const; ///< max over stories
};

/// The journal line of a point (doubles round-trip exactly).
nlohmann::json to_json(const IdaPoint& point);
/// The point of a journal line; std::invalid_argument when a field is missing or malformed.
IdaPoint point_from_json(const nlohmann::json& line);

} // namespace brb::ida
