#include "brb/io/csv.hpp"

#include "brb/io/input_error.hpp"

// fast-cpp-csv-parser copies file names with strncpy into fixed buffers; GCC's middle end
// flags that after inlining even though the header is a system header.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wstringop-truncation"
#include <libfccp/csv.h>
#pragma GCC diagnostic pop

#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace brb::io {
namespace {

/// Comma separated, cells trimmed of spaces and tabs, "..." quoting, blank lines and lines
/// starting with '#' skipped. Cells are read as text and converted by parse_cell.
using ColumnReader =
    ::io::CSVReader<1, ::io::trim_chars<' ', '\t'>, ::io::double_quote_escape<',', '"'>,
                    ::io::throw_on_overflow, ::io::single_and_empty_line_comment<'#'>>;

std::string line_location(std::size_t line) {
  return "line " + std::to_string(line);
}

std::string cell_location(std::size_t line, const std::string& column) {
  return line_location(line) + ", column " + column;
}

std::string quoted_excerpt(std::string_view text) {
  constexpr std::size_t kLongest = 40;
  std::string result = "\"";
  result += text.substr(0, kLongest);
  if (text.size() > kLongest)
    result += "...";
  result += '"';
  return result;
}

struct HeaderLine {
  std::size_t number = 0;
  std::string text;
};

/// The first line of the file that is neither blank nor a '#' comment (the header), for
/// error messages.
HeaderLine header_line_of(const std::filesystem::path& file) {
  std::ifstream stream(file);
  HeaderLine header;
  while (std::getline(stream, header.text)) {
    ++header.number;
    if (!header.text.empty() && header.text.back() == '\r')
      header.text.pop_back();
    const auto first = header.text.find_first_not_of(" \t");
    if (first != std::string::npos && header.text[first] != '#')
      return header;
  }
  return {};
}

std::string header_location(const HeaderLine& header) {
  return line_location(header.number) + " (header)";
}

double parse_cell(const char* cell, const std::string& source, std::size_t line,
                  const std::string& column) {
  const std::string_view text(cell);
  if (text.empty()) {
    throw InputError(source, cell_location(line, column), "expected a number, got an empty cell");
  }
  // from_chars takes no leading '+'; numbers written by other tools may have one.
  const std::string_view digits = text.front() == '+' ? text.substr(1) : text;
  double value = 0.0;
  const auto [end, status] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (status == std::errc::result_out_of_range) {
    throw InputError(source, cell_location(line, column),
                     "expected a finite number within double range, got " + quoted_excerpt(text));
  }
  if (status != std::errc{} || end != digits.data() + digits.size() || digits.empty()) {
    throw InputError(source, cell_location(line, column),
                     "expected a number, got " + quoted_excerpt(text));
  }
  if (!std::isfinite(value)) {
    throw InputError(source, cell_location(line, column),
                     "expected a finite number, got " + quoted_excerpt(text));
  }
  return value;
}

} // namespace

NumericColumn read_numeric_column(const std::filesystem::path& file, const std::string& column) {
  const std::string source = file.string();
  std::error_code status_error;
  const auto status = std::filesystem::status(file, status_error);
  if (!std::filesystem::exists(status)) {
    throw InputError(source, "", "cannot read the file: it does not exist");
  }
  if (std::filesystem::is_directory(status)) {
    throw InputError(source, "", "cannot read the file: it is a directory");
  }

  NumericColumn result;
  try {
    ColumnReader reader(source);
    reader.read_header(::io::ignore_extra_column, column);
    char* cell = nullptr;
    while (reader.read_row(cell)) {
      const std::size_t line = reader.get_file_line();
      result.values.push_back(parse_cell(cell, source, line, column));
      result.lines.push_back(line);
    }
  } catch (const ::io::error::can_not_open_file& error) {
    throw InputError(source, "",
                     std::string("cannot open the file: ") + std::strerror(error.errno_value));
  } catch (const ::io::error::header_missing&) {
    throw InputError(source, "",
                     "the file is empty: expected a header line naming the columns, with a "
                     "column '" +
                         column + "'");
  } catch (const ::io::error::missing_column_in_header&) {
    const HeaderLine header = header_line_of(file);
    throw InputError(source, header_location(header),
                     "no column named '" + column + "'; the header reads " +
                         quoted_excerpt(header.text));
  } catch (const ::io::error::duplicated_column_in_header&) {
    throw InputError(source, header_location(header_line_of(file)),
                     "column '" + column + "' appears more than once");
  } catch (const ::io::error::too_few_columns& error) {
    throw InputError(source, line_location(static_cast<std::size_t>(error.file_line)),
                     "too few cells: expected one per header column, including '" + column + "'");
  } catch (const ::io::error::too_many_columns& error) {
    throw InputError(source, line_location(static_cast<std::size_t>(error.file_line)),
                     "too many cells: expected one per header column");
  } catch (const ::io::error::escaped_string_not_closed& error) {
    throw InputError(source, line_location(static_cast<std::size_t>(error.file_line)),
                     "a quoted cell is not closed");
  } catch (const ::io::error::line_length_limit_exceeded& error) {
    throw InputError(source, line_location(static_cast<std::size_t>(error.file_line)),
                     "line too long");
  } catch (const ::io::error::base& error) {
    throw InputError(source, "", std::string("malformed CSV: ") + error.what());
  }

  if (result.values.empty()) {
    throw InputError(source, "",
                     "no data rows: expected at least one row below the header with a value "
                     "in column '" +
                         column + "'");
  }
  return result;
}

std::string format_number(double value) {
  std::array<char, 32> buffer{};
  const auto [end, status] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  if (status != std::errc{})
    throw std::logic_error("format_number: buffer too small");
  return std::string(buffer.data(), end);
}

std::string significant(double value, int digits) {
  std::ostringstream text;
  text << std::setprecision(digits) << value;
  return text.str();
}

NumericTable::NumericTable(std::vector<std::string> columns) : columns_(std::move(columns)) {
  if (columns_.empty())
    throw std::invalid_argument("NumericTable: no columns");
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (i > 0)
      text_ += ',';
    text_ += columns_[i];
  }
  text_ += '\n';
}

void NumericTable::append_row(std::span<const double> values) {
  if (values.size() != columns_.size()) {
    throw std::invalid_argument("NumericTable: a row of " + std::to_string(values.size()) +
                                " values for " + std::to_string(columns_.size()) + " columns");
  }
  std::array<char, 32> buffer{};
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0)
      text_ += ',';
    const auto [end, status] =
        std::to_chars(buffer.data(), buffer.data() + buffer.size(), values[i]);
    if (status != std::errc{})
      throw std::logic_error("NumericTable: buffer too small");
    text_.append(buffer.data(), end);
  }
  text_ += '\n';
  ++row_count_;
}

} // namespace brb::io
