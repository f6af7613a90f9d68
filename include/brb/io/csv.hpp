// CSV input and output: one numeric column read by name (fast-cpp-csv-parser for the
// splitting, std::from_chars for exact numbers) and numeric tables written at full precision.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace brb::io {

/// The values of one column of a CSV file, with the file line each came from.
struct NumericColumn {
  std::vector<double> values;
  std::vector<std::size_t> lines; ///< 1-based line number in the file of values[i]
};

/// Reads the column named `column` of a CSV file: a header line naming the columns, then one
/// row per line, comma separated. Other columns are ignored; cells may be quoted ("...") and
/// padded with spaces; blank lines and lines starting with '#' are skipped.
/// Throws InputError naming the file (and the line and column) when the file cannot be read
/// or is empty, the header lacks the column, a value is missing, not a number or not finite,
/// or there is no data row.
NumericColumn read_numeric_column(const std::filesystem::path& file, const std::string& column);

/// The shortest decimal text that reads back to exactly `value` (std::to_chars).
std::string format_number(double value);

/// `value` with `digits` significant digits (iostream's default float format), for reports
/// meant to be read, not read back.
std::string significant(double value, int digits);

/// A CSV table of numbers built in memory: a header line, then one line per row, '\n' line
/// endings, every number at full (shortest round-trip) precision.
class NumericTable {
public:
  explicit NumericTable(std::vector<std::string> columns);

  /// Appends a row; throws std::invalid_argument unless it has one value per column.
  void append_row(std::span<const double> values);

  const std::vector<std::string>& columns() const { return columns_; }
  std::size_t row_count() const { return row_count_; }
  /// The CSV text, ready to be written (see atomic_file.hpp).
  const std::string& text() const { return text_; }

private:
  std::vector<std::string> columns_;
  std::size_t row_count_ = 0;
  std::string text_;
};

} // namespace brb::io
