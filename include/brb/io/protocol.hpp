// Loading protocols for virtual cyclic tests of a brace: the history of the brace's axial
// deformation (mm, elongation positive) that `brb cyclic` imposes, built in (the Girona and
// UC San Diego test programmes, BRB_SOURCE_FACTS sections 7 and 8), given as cycles in a
// protocol JSON file, or read point by point from a CSV history (DESIGN.md sections 7-9).
//
// Protocol JSON file (comments allowed; every error names the file, the JSON path and what
// was expected):
//
//   { "units": "dy",                    // "mm", or "dy": multiples of the brace's yield
//                                       // deformation; required with "cycles" (a protocol
//                                       // with unit-less amplitudes is rejected)
//     "cycles": [ {"amplitude": 0.25, "cycles": 1},   // amplitude > 0, in "units"
//                 {"amplitude": 2, "cycles": 2} ],     // cycles: a positive integer
//     "max_step": 0.1 }                 // optional, > 0, in "units": the largest change of
//                                       // deformation between two points; default: the
//                                       // caller's (mm)
//
// or a built-in protocol, which excludes "cycles":
//
//   { "builtin": "girona", "final_cycles": 4, "max_step": 0.05 }
//   { "builtin": "ucsd", "units": "mm", "max_step": 0.5 }
//
// "final_cycles" (a positive integer, the number of cycles at 5 dy) is required with
// "girona" and not allowed otherwise. With "builtin", "units" applies to max_step only and
// is optional, default "dy".
//
// Every full cycle of amplitude A goes 0 -> +A -> -A -> 0 (tension first). Each leg between
// turning points is cut into equal steps of at most max_step, and the turning points are
// points of the history exactly.
//
// CSV history: a header line, then one row per point; the column `deformation` (mm) is
// read, the others are ignored (csv.hpp: quotes, spaces, blank lines and '#' comment lines
// are tolerated). A history that does not start at 0 is given a first point 0.0; points
// farther apart than max_step (the caller's default) are joined by equally spaced points.
// Cycles are counted by sign reversals: the sign of the first non-zero deformation is the
// leading direction (tension for the usual protocols) and a full cycle ends at each point
// that is back on the leading side or at zero after a point on the other side, i.e. after
// an excursion each way. For a tension-first history: a cycle ends each time the
// deformation goes from negative to non-negative; the point doing so closes the cycle.
// Points after the last such return form a last, incomplete cycle. Every reversal counts:
// a measured record that chatters about zero must be cleaned first.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace brb::io {

/// A displacement-controlled loading history of the brace's axial deformation (mm,
/// elongation positive), as the analysis steps through it.
struct LoadingProtocol {
  /// "girona", "ucsd", or the protocol file's name as the caller wrote it.
  std::string name;
  /// mm; the first value is 0.0 and consecutive points are at most max_step apart.
  std::vector<double> deformation;
  /// One per point: the 1-based index of the full cycle the point belongs to (0 for the
  /// initial point); a cycle's last point is its return to zero.
  std::vector<int> cycle;
  /// mm, one per full cycle (cycle k -> cycle_amplitude[k - 1]): the amplitude asked for, or
  /// for a CSV history the peak |deformation| within the cycle.
  std::vector<double> cycle_amplitude;

  std::size_t cycle_count() const { return cycle_amplitude.size(); }
};

/// `cycles` full cycles at the same amplitude (mm), one entry of a cyclic protocol.
struct CycleGroup {
  double amplitude = 0.0;
  int cycles = 0;
};

/// Points of a protocol are at most max_step apart up to this relative tolerance, so that a
/// leg that is a whole number of steps long (1 dy in steps of 0.1 dy) is not given one step
/// more because the conversion to mm rounded its length up by an ulp.
inline constexpr double step_rounding_tolerance = 1e-9;

/// The most points a protocol may have (a guard against a max_step far too small for the
/// amplitudes, which would exhaust memory long before the analysis could run it).
inline constexpr std::size_t max_protocol_points = 10'000'000;

/// Reads a protocol JSON file (extension .json) or a CSV history (.csv); the schemas are at the
/// top of this header. `yield_deformation` (mm, > 0) converts "dy" units; `default_max_step`
/// (mm, > 0) applies when the file gives no max_step, and always to CSV histories.
/// Throws InputError naming the file (with the JSON path or CSV line) when the file is
/// unreadable, of another type, does not follow the schema, or would give more than
/// max_protocol_points points; std::invalid_argument when
/// yield_deformation or default_max_step is not a positive finite number.
LoadingProtocol read_protocol(const std::filesystem::path& file, double yield_deformation,
                              double default_max_step);

/// The Girona protocol (Palazzo et al. 2009, BRB_SOURCE_FACTS section 7): one cycle each at
/// 0.25, 0.5, 0.75, 1, 2 and 2.5 dy, then `final_cycles` cycles at 5 dy (the tests repeated
/// 5 dy until failure). Named "girona".
LoadingProtocol girona_protocol(double yield_deformation, int final_cycles, double max_step);

/// The UC San Diego G-series protocol (Newell, Uang & Benzoni 2006, BRB_SOURCE_FACTS
/// section 8): 5 cycles at dy, 2 at 2 dy, 1 at 3 dy, 1 at 4 dy. Named "ucsd".
LoadingProtocol ucsd_protocol(double yield_deformation, double max_step);

/// Full cycles of the given amplitudes (mm), in order: each goes 0 -> +A -> -A -> 0 (tension
/// first), each leg in equal steps of at most max_step (mm), turning points included exactly.
/// Throws std::invalid_argument for no groups, an amplitude or max_step that is not a
/// positive finite number, a cycle count below 1, or more than max_protocol_points points.
LoadingProtocol cyclic_protocol(std::string name, const std::vector<CycleGroup>& groups,
                                double max_step);

/// A protocol through the given points (mm) in order: 0.0 put first unless the first point is
/// 0, legs longer than max_step cut into equal steps, cycles counted by sign reversals as
/// described at the top of this header. Throws std::invalid_argument for no points, a
/// non-finite point, points that are all zero, a max_step that is not a positive finite
/// number, or more than max_protocol_points points.
LoadingProtocol history_protocol(std::string name, const std::vector<double>& points,
                                 double max_step);

} // namespace brb::io
