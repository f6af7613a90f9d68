// Laboratory force-deformation records (issue 4): a CSV file whose columns are named in its
// header, in the laboratory's units (e.g. kip and inch), read into N and mm at the edge.
// The reference object of a validation metrics file describes such a record:
//
//   "reference": {"file": "shared:data/brb_tests/.../PC160/force_deformation.csv",
//                 "columns": {"force": "Force[kip]", "deformation": "Deformation[in]"},
//                 "units": {"force": "kip", "length": "in"},
//                 "exclude_rows": [[19475, 20050], [33509, null]] }
//
// Rows are the data rows below the header, numbered from 0 (blank lines and '#' comment
// lines are not rows), the numbering of the record's source (gaaraujo/BRB-Calibration,
// raw_trim_ranges.yaml). An excluded range [begin, end) is half-open; end null runs to the
// end of the file.
#pragma once

#include "brb/io/csv.hpp"
#include "brb/io/json_input.hpp"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace brb::io {

/// Data rows [begin, end) left out of a record (0-based; no end: to the end of the file).
struct RowRange {
  std::size_t begin = 0;
  std::optional<std::size_t> end;

  bool contains(std::size_t row) const { return row >= begin && (!end || row < *end); }
};

/// How to read a record: the two column names, the units of the file and excluded rows.
struct ForceRecordFormat {
  std::string force_column;
  std::string deformation_column;
  /// "N", "kN" or "kip".
  std::string force_unit = "N";
  /// "mm", "m" or "in".
  std::string length_unit = "mm";
  std::vector<RowRange> excluded_rows;
};

/// N per unit of force: "N" 1, "kN" 1000, "kip" 4448.2216152605 (1 kip = 1000 lbf, lbf =
/// 0.45359237 kg x 9.80665 m/s^2, exact by definition). Nothing for another unit.
std::optional<double> newtons_per_force_unit(const std::string& unit);
/// mm per unit of length: "mm" 1, "m" 1000, "in" 25.4 (exact). Nothing for another unit.
std::optional<double> millimetres_per_length_unit(const std::string& unit);

/// A record in N and mm, with the rows kept.
struct ForceRecord {
  std::vector<double> deformation; ///< mm, elongation positive
  std::vector<double> force;       ///< N, tension positive
  std::vector<std::size_t> row;    ///< 0-based data row of the file each point came from
  std::vector<std::size_t> line;   ///< 1-based line of the file

  std::size_t size() const { return force.size(); }
};

/// Reads the record `file` as `format` says. Throws InputError naming the file (and the line
/// and column) when it cannot be read, lacks a column, a cell is not a finite number, a unit
/// is unknown, an excluded range is reversed, or no row is left after the exclusions.
ForceRecord read_force_record(const std::filesystem::path& file, const ForceRecordFormat& format);

/// A record file and how to read it, as given by a reference object.
struct ForceRecordReference {
  std::filesystem::path file; ///< resolved path
  ForceRecordFormat format;
};

/// Reads a reference object (schema at the top of this header) found in a JSON file.
/// `file` is resolved: "shared:REST" against `shared_directory`, a relative path against
/// `base_directory` (normally the JSON file's directory). Errors name the JSON path.
ForceRecordReference read_force_record_reference(const JsonValue& object,
                                                 const std::filesystem::path& base_directory,
                                                 const std::filesystem::path& shared_directory);

/// The record's force (N) at each point of a protocol CSV whose column `row_column`
/// (`rows`, read with read_numeric_column) names the record's 0-based data row of each point;
/// NaN where it is negative (not a record point). Throws InputError (protocol file, line) for
/// a row the record does not keep.
std::vector<double> record_force_at_rows(const ForceRecord& record, const NumericColumn& rows,
                                         const std::filesystem::path& protocol_file,
                                         const std::string& row_column);

/// The project's shared directory for "shared:" paths: the first ancestor A of `start` (an
/// absolute or relative directory) that has a sub-directory A/shared; nothing when none has.
std::optional<std::filesystem::path> find_shared_directory(const std::filesystem::path& start);

} // namespace brb::io
