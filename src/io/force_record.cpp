#include "brb/io/force_record.hpp"

#include "brb/io/csv.hpp"
#include "brb/io/input_error.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

namespace brb::io {
namespace {

constexpr std::string_view kSharedPrefix = "shared:";

std::string range_location(std::size_t index) {
  return "excluded row range " + std::to_string(index);
}

/// A whole, non-negative JSON number as a row index.
std::size_t row_index(const JsonValue& value, std::string_view meaning) {
  const double number = value.number(meaning);
  if (number < 0.0 || number != std::floor(number) || number > 1e15) {
    throw value.error(std::string(meaning) + ": expected a whole number >= 0 (got " +
                      describe_json_value(value.json()) + ")");
  }
  return static_cast<std::size_t>(number);
}

} // namespace

std::optional<double> newtons_per_force_unit(const std::string& unit) {
  if (unit == "N")
    return 1.0;
  if (unit == "kN")
    return 1000.0;
  if (unit == "kip")
    return 4448.2216152605; // 1000 x 0.45359237 kg x 9.80665 m/s^2
  return std::nullopt;
}

std::optional<double> millimetres_per_length_unit(const std::string& unit) {
  if (unit == "mm")
    return 1.0;
  if (unit == "m")
    return 1000.0;
  if (unit == "in")
    return 25.4;
  return std::nullopt;
}

ForceRecord read_force_record(const std::filesystem::path& file, const ForceRecordFormat& format) {
  const std::string source = file.string();
  const auto newtons = newtons_per_force_unit(format.force_unit);
  if (!newtons) {
    throw InputError(source, "",
                     "unknown force unit \"" + format.force_unit + "\": expected N, kN or kip");
  }
  const auto millimetres = millimetres_per_length_unit(format.length_unit);
  if (!millimetres) {
    throw InputError(source, "",
                     "unknown length unit \"" + format.length_unit + "\": expected mm, m or in");
  }
  for (std::size_t i = 0; i < format.excluded_rows.size(); ++i) {
    const RowRange& range = format.excluded_rows[i];
    if (range.end && *range.end <= range.begin) {
      throw InputError(source, range_location(i),
                       "expected begin < end, got [" + std::to_string(range.begin) + ", " +
                           std::to_string(*range.end) + ")");
    }
  }

  // Each column is read by its header name (files differ in column order); every data row
  // has both cells, so the two columns list the same lines.
  const NumericColumn forces = read_numeric_column(file, format.force_column);
  const NumericColumn deformations = read_numeric_column(file, format.deformation_column);
  if (forces.lines != deformations.lines) {
    throw InputError(source, "",
                     "the columns '" + format.force_column + "' and '" + format.deformation_column +
                         "' list different rows");
  }

  ForceRecord record;
  for (std::size_t row = 0; row < forces.values.size(); ++row) {
    bool excluded = false;
    for (const RowRange& range : format.excluded_rows)
      excluded = excluded || range.contains(row);
    if (excluded)
      continue;
    record.force.push_back(forces.values[row] * *newtons);
    record.deformation.push_back(deformations.values[row] * *millimetres);
    record.row.push_back(row);
    record.line.push_back(forces.lines[row]);
  }
  if (record.force.empty()) {
    throw InputError(source, "",
                     "no data row left after the excluded row ranges (the file has " +
                         std::to_string(forces.values.size()) + " rows)");
  }
  return record;
}

ForceRecordReference read_force_record_reference(const JsonValue& object,
                                                 const std::filesystem::path& base_directory,
                                                 const std::filesystem::path& shared_directory) {
  object.expect_object({"file", "columns", "units", "exclude_rows"}, "a record reference");
  ForceRecordReference reference;

  const std::string file = object.at("file", "the record's CSV file").string("record file");
  if (file.starts_with(kSharedPrefix)) {
    reference.file = shared_directory / file.substr(kSharedPrefix.size());
  } else {
    reference.file = std::filesystem::path(file).is_absolute() ? std::filesystem::path(file)
                                                               : base_directory / file;
  }

  const JsonValue columns =
      object.at("columns", "the record's column names {\"force\": ..., \"deformation\": ...}");
  columns.expect_object({"force", "deformation"}, "the column names");
  reference.format.force_column = columns.at("force", "force column name").string("column name");
  reference.format.deformation_column =
      columns.at("deformation", "deformation column name").string("column name");

  const JsonValue units =
      object.at("units", "the record's units {\"force\": N|kN|kip, \"length\": mm|m|in}");
  units.expect_object({"force", "length"}, "the units");
  const JsonValue force_unit = units.at("force", "force unit: N, kN or kip");
  reference.format.force_unit = force_unit.string("force unit");
  if (!newtons_per_force_unit(reference.format.force_unit))
    throw force_unit.error("unknown force unit: expected \"N\", \"kN\" or \"kip\"");
  const JsonValue length_unit = units.at("length", "length unit: mm, m or in");
  reference.format.length_unit = length_unit.string("length unit");
  if (!millimetres_per_length_unit(reference.format.length_unit))
    throw length_unit.error("unknown length unit: expected \"mm\", \"m\" or \"in\"");

  if (const auto excluded = object.find("exclude_rows")) {
    const std::size_t count = excluded->expect_array(1000, "a list of row ranges [begin, end]");
    for (std::size_t i = 0; i < count; ++i) {
      const JsonValue range = excluded->element(i);
      if (range.expect_array(2, "a row range [begin, end or null]") != 2)
        throw range.error("expected a row range [begin, end or null] of two entries");
      RowRange rows;
      rows.begin = row_index(range.element(0), "first excluded row");
      const JsonValue end = range.element(1);
      if (!end.json().is_null()) {
        rows.end = row_index(end, "end of the excluded rows (exclusive)");
        if (*rows.end <= rows.begin)
          throw end.error("end of the excluded rows must be > its begin (or null)");
      }
      reference.format.excluded_rows.push_back(rows);
    }
  }
  return reference;
}

std::optional<std::filesystem::path> find_shared_directory(const std::filesystem::path& start) {
  std::error_code error;
  std::filesystem::path directory = std::filesystem::absolute(start, error);
  if (error)
    return std::nullopt;
  while (true) {
    if (std::filesystem::is_directory(directory / "shared", error))
      return directory / "shared";
    if (!directory.has_parent_path() || directory.parent_path() == directory)
      return std::nullopt;
    directory = directory.parent_path();
  }
}

std::vector<double> record_force_at_rows(const ForceRecord& record, const NumericColumn& rows,
                                         const std::filesystem::path& protocol_file,
                                         const std::string& row_column) {
  std::vector<double> force(rows.values.size(), std::nan(""));
  for (std::size_t k = 0; k < rows.values.size(); ++k) {
    if (rows.values[k] < 0.0)
      continue;
    const auto row = static_cast<std::size_t>(rows.values[k]);
    const auto found = std::lower_bound(record.row.begin(), record.row.end(), row);
    if (found == record.row.end() || *found != row) {
      throw InputError(protocol_file.string(), "line " + std::to_string(rows.lines[k]),
                       row_column + " " + std::to_string(row) + " is not a kept row of the record");
    }
    force[k] = record.force[static_cast<std::size_t>(found - record.row.begin())];
  }
  return force;
}

} // namespace brb::io
