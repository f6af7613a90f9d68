// Ground-motion records (DESIGN.md section 2, io): PEER AT2 files, CSV files and single-column
// text files read into one uniformly sampled acceleration history in mm/s^2.
//
// Units are converted here, at the edge: a record in g is multiplied by the standard gravity
// g = 9806.65 mm/s^2 (exact by definition, CGPM 1901), one in m/s^2 by 1000. The record's
// scale factor is applied after the units. Every malformed file throws InputError naming the
// file, the line (lines are counted by '\n'; a "\r\r\n" line end is one line end) and what was
// expected.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace brb::io {

/// Standard gravity in mm/s^2 (exact by definition).
inline constexpr double kStandardGravity = 9806.65;

/// A uniformly sampled ground acceleration: acceleration[i] is the value at time i * dt (the
/// first sample at t = 0), in mm/s^2, after the units and the scale factor.
struct GroundMotion {
  std::string name; ///< the file name without its extension
  double dt = 0.0;  ///< time step, s (> 0)
  std::vector<double> acceleration;

  double duration() const {
    return acceleration.empty() ? 0.0 : dt * static_cast<double>(acceleration.size() - 1);
  }
  /// Peak ground acceleration max |a|, mm/s^2.
  double peak_acceleration() const;
};

enum class AccelerationUnits { g, m_per_s2, mm_per_s2 };

/// mm/s^2 per unit: g 9806.65, m/s^2 1000, mm/s^2 1.
double millimetres_per_s2(AccelerationUnits units);
/// The text form: "g", "m/s^2", "mm/s^2".
std::string_view units_name(AccelerationUnits units);
/// The units named `text` ("g", "m/s^2" or "mm/s^2", exactly); nothing for another text.
std::optional<AccelerationUnits> acceleration_units_named(std::string_view text);
/// As acceleration_units_named, but an unknown text throws InputError(source, field, ...), e.g.
/// source "command line", field "--units"; or a JSON file and the JSON path of its field.
AccelerationUnits parse_acceleration_units(std::string_view text, const std::string& source,
                                           const std::string& field);

/// Reads a PEER strong-motion file (.AT2): header lines, the last of which holds
/// `NPTS= n, DT= dt SEC` (anything after it on the line is ignored), then the n values, a few
/// per line, whitespace separated. Handles the NGA and the older PEER headers, CRLF and
/// "\r\r\n" line ends, blank lines, and fixed-width Fortran layouts (e.g. 8F10.5) whose
/// numbers touch (`-0.1234567-0.2345678`): a line that does not split on whitespace is split
/// into fields of the width the header's Fortran format names (10 when it names none).
/// Units come from the header ("UNITS OF G", "units are (g)"), unless `units_override` gives
/// them; a velocity or displacement record is refused. Errors (InputError): missing file, no
/// NPTS/DT line, NPTS or DT not a positive number, a value that is not a number, NPTS not
/// equal to the count read (both named), empty record, units neither stated nor given,
/// `scale` not finite or zero.
GroundMotion read_peer_at2(const std::filesystem::path& file,
                           std::optional<AccelerationUnits> units_override = std::nullopt,
                           double scale = 1.0);

/// Reads a CSV record (fast-cpp-csv-parser): either a header naming the columns `time` and
/// `accel` (other columns ignored), whose times must be uniformly spaced (to 1e-6 dt; dt is
/// taken from them, and a given `dt` must agree), or a single column of values, headed
/// `accel` or without a header, sampled at the given `dt`. Blank lines and lines starting with
/// '#' are skipped. The file states no units: the caller gives them.
GroundMotion read_acceleration_csv(const std::filesystem::path& file, AccelerationUnits units,
                                   std::optional<double> dt = std::nullopt, double scale = 1.0);

/// Reads a single-column text record (e.g. the FEMA P695 `.rec` files): one value per line,
/// no header, blank lines skipped; the time step and units come from the caller.
GroundMotion read_acceleration_column(const std::filesystem::path& file, AccelerationUnits units,
                                      double dt, double scale = 1.0);

enum class GroundMotionFormat { automatic, at2, csv, column };

/// "auto", "at2", "csv", "column"; nothing for another text.
std::optional<GroundMotionFormat> ground_motion_format_named(std::string_view text);

struct GroundMotionOptions {
  /// automatic: from the extension, .at2 (any case) -> at2, .csv -> csv, .rec or .txt -> column.
  GroundMotionFormat format = GroundMotionFormat::automatic;
  /// Required for csv and column files; overrides the header of an AT2 file.
  std::optional<AccelerationUnits> units;
  /// s; required for column files and single-column CSV. A file that states its own time step
  /// (AT2, CSV with times) must agree with it (relative 1e-6).
  std::optional<double> dt;
  double scale = 1.0;
};

/// Reads `file` in the format the options name (or its extension implies).
GroundMotion load_ground_motion(const std::filesystem::path& file,
                                const GroundMotionOptions& options = {});

} // namespace brb::io
