#include "brb/io/ground_motion.hpp"

#include "brb/io/csv.hpp"
#include "brb/io/input_error.hpp"

// fast-cpp-csv-parser copies file names with strncpy into fixed buffers; GCC's middle end
// flags that after inlining even though the header is a system header (as in csv.cpp).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wstringop-truncation"
#include <libfccp/csv.h>
#pragma GCC diagnostic pop

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>
#include <system_error>

namespace brb::io {
namespace {

/// PEER headers have 4 lines; a few more are tolerated before the NPTS line.
constexpr std::size_t kMostHeaderLines = 12;
/// Field width of a fixed-width line when the header names no Fortran format (8F10.5).
constexpr std::size_t kDefaultFieldWidth = 10;
/// Relative tolerance on a uniform time step (CSV times, a given dt against the file's).
constexpr double kTimeStepTolerance = 1e-6;

/// One value per line: cells trimmed of spaces, tabs and stray carriage returns ("\r\r\n"
/// line ends), blank lines and '#' comments skipped. A second cell is an error.
using ValueReader =
    ::io::CSVReader<1, ::io::trim_chars<' ', '\t', '\r'>, ::io::double_quote_escape<',', '"'>,
                    ::io::throw_on_overflow, ::io::single_and_empty_line_comment<'#'>>;

std::string line_location(std::size_t line) {
  return "line " + std::to_string(line);
}

std::string excerpt(std::string_view text) {
  constexpr std::size_t kLongest = 40;
  std::string result = "\"";
  result += text.substr(0, kLongest);
  if (text.size() > kLongest)
    result += "...";
  return result + "\"";
}

std::string number_text(double value) {
  std::ostringstream stream;
  stream.precision(10);
  stream << value;
  return stream.str();
}

std::string upper_case(std::string_view text) {
  std::string result(text);
  std::transform(result.begin(), result.end(), result.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return result;
}

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && is_space(text.front()))
    text.remove_prefix(1);
  while (!text.empty() && is_space(text.back()))
    text.remove_suffix(1);
  return text;
}

/// A finite number spelled exactly by `text` (a leading '+' allowed; ".5E-02" Fortran style).
std::optional<double> number_in(std::string_view text) {
  if (!text.empty() && text.front() == '+')
    text.remove_prefix(1);
  if (text.empty())
    return std::nullopt;
  double value = 0.0;
  const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (status != std::errc{} || end != text.data() + text.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

void check_readable(const std::filesystem::path& file) {
  std::error_code error;
  const auto status = std::filesystem::status(file, error);
  if (!std::filesystem::exists(status))
    throw InputError(file.string(), "", "cannot read the file: it does not exist");
  if (std::filesystem::is_directory(status))
    throw InputError(file.string(), "", "cannot read the file: it is a directory");
}

void check_scale(const std::filesystem::path& file, double scale) {
  if (!std::isfinite(scale) || scale == 0.0) {
    throw InputError(file.string(), "scale",
                     "expected a finite, non-zero scale factor, got " + number_text(scale));
  }
}

void check_given_time_step(const std::filesystem::path& file, double dt) {
  if (!std::isfinite(dt) || dt <= 0.0) {
    throw InputError(file.string(), "dt", "expected a time step > 0 s, got " + number_text(dt));
  }
}

/// The lines of a text file, without their line ends; "\r\n" and "\r\r\n" end one line.
std::vector<std::string> lines_of_file(const std::filesystem::path& file) {
  std::ifstream stream(file, std::ios::binary);
  if (!stream) {
    throw InputError(file.string(), "",
                     std::string("cannot open the file: ") + std::strerror(errno));
  }
  std::vector<std::string> lines;
  for (std::string line; std::getline(stream, line);) {
    while (!line.empty() && line.back() == '\r')
      line.pop_back();
    lines.push_back(std::move(line));
  }
  return lines;
}

// ---------------------------------------------------------------------------------- AT2 ----

struct At2Header {
  std::size_t npts_line = 0; ///< 0-based index of the NPTS/DT line
  long long npts = 0;
  double dt = 0.0;
  std::optional<AccelerationUnits> units;
  std::size_t field_width = kDefaultFieldWidth;
};

/// The token after `key` and its '=' (or ':') in `upper`, up to a space or a comma.
std::optional<std::string_view> value_after_key(std::string_view upper, std::string_view key,
                                                std::size_t from) {
  const auto at = upper.find(key, from);
  if (at == std::string_view::npos)
    return std::nullopt;
  std::size_t i = at + key.size();
  while (i < upper.size() && is_space(upper[i]))
    ++i;
  if (i >= upper.size() || (upper[i] != '=' && upper[i] != ':'))
    return std::nullopt;
  ++i;
  while (i < upper.size() && is_space(upper[i]))
    ++i;
  std::size_t end = i;
  while (end < upper.size() && !is_space(upper[end]) && upper[end] != ',')
    ++end;
  return upper.substr(i, end - i);
}

/// Units named after the word UNITS in a header line: "UNITS OF G", "units are (g)".
std::optional<std::string> units_text(std::string_view upper) {
  const auto at = upper.find("UNITS");
  if (at == std::string_view::npos)
    return std::nullopt;
  std::istringstream words{std::string(upper.substr(at + 5))};
  for (std::string word; words >> word;) {
    std::erase_if(word, [](char c) { return c == '(' || c == ')' || c == ':' || c == '='; });
    while (!word.empty() && (word.back() == '.' || word.back() == ','))
      word.pop_back();
    if (word.empty() || word == "OF" || word == "ARE" || word == "IN" || word == "IS")
      continue;
    return word;
  }
  return std::nullopt;
}

std::optional<AccelerationUnits> header_units_named(const std::string& word) {
  if (word == "G" || word == "G'S" || word == "GS")
    return AccelerationUnits::g;
  for (const char* spelling : {"M/S^2", "M/S/S", "M/S2", "M/SEC/SEC", "M/SEC^2", "M/SEC2"}) {
    if (word == spelling)
      return AccelerationUnits::m_per_s2;
  }
  for (const char* spelling : {"MM/S^2", "MM/S/S", "MM/S2", "MM/SEC/SEC", "MM/SEC^2", "MM/SEC2"}) {
    if (word == spelling)
      return AccelerationUnits::mm_per_s2;
  }
  return std::nullopt;
}

At2Header read_at2_header(const std::filesystem::path& file, const std::vector<std::string>& lines,
                          bool units_given) {
  const std::string source = file.string();
  At2Header header;
  const std::size_t searched = std::min(lines.size(), kMostHeaderLines);
  std::size_t found = searched;
  for (std::size_t i = 0; i < searched && found == searched; ++i) {
    if (upper_case(lines[i]).find("NPTS") != std::string::npos)
      found = i;
  }
  if (found == searched) {
    throw InputError(source, "",
                     "no NPTS/DT line in the first " + std::to_string(searched) +
                         " lines: expected a PEER AT2 header whose last line reads like "
                         "\"NPTS=  2000, DT= .02000 SEC\"");
  }
  header.npts_line = found;
  const std::string location = line_location(found + 1);
  const std::string upper = upper_case(lines[found]);

  const auto npts_text = value_after_key(upper, "NPTS", 0);
  const auto npts = npts_text ? number_in(*npts_text) : std::nullopt;
  if (!npts || *npts < 0.0 || *npts != std::floor(*npts) || *npts > 1e12) {
    throw InputError(source, location,
                     "expected NPTS= followed by a whole number of points, got " +
                         excerpt(trimmed(lines[found])));
  }
  header.npts = static_cast<long long>(*npts);
  const auto dt_text = value_after_key(upper, "DT", upper.find("NPTS") + 4);
  const auto dt = dt_text ? number_in(*dt_text) : std::nullopt;
  if (!dt) {
    throw InputError(source, location,
                     "expected DT= followed by the time step in seconds, got " +
                         excerpt(trimmed(lines[found])));
  }
  if (*dt <= 0.0) {
    throw InputError(source, location, "expected a time step DT > 0 s, got " + number_text(*dt));
  }
  header.dt = *dt;

  // Kind, units and layout from the lines above NPTS.
  static const std::regex fortran_format(R"((^|[\s(,])\d*[FEDG](\d+)\.\d+)");
  for (std::size_t i = 0; i < found; ++i) {
    const std::string text = upper_case(lines[i]);
    const bool acceleration = text.find("ACCELERATION") != std::string::npos;
    if (!acceleration && (text.find("VELOCITY") != std::string::npos ||
                          text.find("DISPLACEMENT") != std::string::npos)) {
      throw InputError(source, line_location(i + 1),
                       "this is a velocity or displacement record (" + excerpt(trimmed(lines[i])) +
                           "); expected an acceleration record");
    }
    if (const auto word = units_text(text); word && !header.units) {
      header.units = header_units_named(*word);
      if (!header.units && !units_given) {
        throw InputError(source, line_location(i + 1),
                         "the header gives the units \"" + *word +
                             "\"; expected g, m/s^2 or mm/s^2 (or give the units, e.g. "
                             "--units mm/s^2 with --scale 10 for cm/s^2)");
      }
    }
    std::smatch match;
    if (std::regex_search(text, match, fortran_format)) {
      const auto width = std::stoul(match[2].str());
      if (width > 0 && width < 100)
        header.field_width = width;
    }
  }
  return header;
}

/// The numbers of one data line: split on whitespace, or, when a token is not a number
/// (numbers that touch in a fixed-width layout), into fields of `width` characters.
void append_values(std::string_view line, std::size_t width, const std::string& source,
                   std::size_t line_number, std::vector<double>& values) {
  std::vector<double> parsed;
  std::string_view bad_token;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i]))
      ++i;
    std::size_t end = i;
    while (end < line.size() && !is_space(line[end]))
      ++end;
    if (end == i)
      break;
    const std::string_view token = line.substr(i, end - i);
    const auto value = number_in(token);
    if (!value) {
      bad_token = token;
      break;
    }
    parsed.push_back(*value);
    i = end;
  }
  if (bad_token.empty()) {
    values.insert(values.end(), parsed.begin(), parsed.end());
    return;
  }

  // Fixed-width fields (Fortran nFw.d): the line's own columns, trailing blanks ignored.
  const std::string_view content = line.substr(0, line.find_last_not_of(" \t\r") + 1);
  parsed.clear();
  for (std::size_t start = 0; start < content.size(); start += width) {
    const std::string_view field = trimmed(content.substr(start, width));
    const auto value = number_in(field);
    if (!value) {
      throw InputError(source, line_location(line_number),
                       "expected numbers separated by blanks or in fields of " +
                           std::to_string(width) + " characters, got " + excerpt(bad_token));
    }
    parsed.push_back(*value);
  }
  values.insert(values.end(), parsed.begin(), parsed.end());
}

// ---------------------------------------------------------------------------------- CSV ----

void scale_into_millimetres(std::vector<double>& values, AccelerationUnits units, double scale) {
  const double factor = millimetres_per_s2(units) * scale;
  for (double& value : values)
    value *= factor;
}

/// Values of a file holding one number per line, without a header (fast-cpp-csv-parser).
std::vector<double> read_value_per_line(const std::filesystem::path& file) {
  const std::string source = file.string();
  std::vector<double> values;
  try {
    ValueReader reader(source);
    reader.set_header("accel");
    char* cell = nullptr;
    while (reader.read_row(cell)) {
      const auto value = number_in(trimmed(cell));
      if (!value) {
        throw InputError(source, line_location(static_cast<std::size_t>(reader.get_file_line())),
                         "expected one number per line (an acceleration), got " + excerpt(cell));
      }
      values.push_back(*value);
    }
  } catch (const ::io::error::can_not_open_file& error) {
    throw InputError(source, "",
                     std::string("cannot open the file: ") + std::strerror(error.errno_value));
  } catch (const ::io::error::too_many_columns& error) {
    throw InputError(source, line_location(static_cast<std::size_t>(error.file_line)),
                     "expected one value per line, got more than one cell");
  } catch (const ::io::error::escaped_string_not_closed& error) {
    throw InputError(source, line_location(static_cast<std::size_t>(error.file_line)),
                     "a quoted cell is not closed");
  } catch (const ::io::error::line_length_limit_exceeded& error) {
    throw InputError(source, line_location(static_cast<std::size_t>(error.file_line)),
                     "line too long");
  } catch (const ::io::error::base& error) {
    throw InputError(source, "", std::string("malformed file: ") + error.what());
  }
  return values;
}

/// The first line that is neither blank nor a '#' comment (UTF-8 byte-order mark removed),
/// with its 1-based number; nothing for a file without one.
std::optional<std::pair<std::size_t, std::string>>
first_content_line(const std::filesystem::path& file) {
  const std::vector<std::string> lines = lines_of_file(file);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::string_view text = lines[i];
    if (i == 0 && text.starts_with("\xEF\xBB\xBF"))
      text.remove_prefix(3);
    text = trimmed(text);
    if (!text.empty() && text.front() != '#')
      return std::pair{i + 1, std::string(text)};
  }
  return std::nullopt;
}

std::vector<std::string> header_cells(std::string_view line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    std::string_view cell = trimmed(
        line.substr(start, comma == std::string_view::npos ? line.size() - start : comma - start));
    if (cell.size() >= 2 && cell.front() == '"' && cell.back() == '"')
      cell = cell.substr(1, cell.size() - 2);
    cells.emplace_back(cell);
    if (comma == std::string_view::npos)
      return cells;
    start = comma + 1;
  }
}

/// dt of uniformly spaced times; each time within kTimeStepTolerance dt of its grid point.
double uniform_time_step(const std::string& source, const NumericColumn& times) {
  const std::size_t count = times.values.size();
  if (count < 2) {
    throw InputError(source, line_location(times.lines.front()),
                     "expected at least two rows to take the time step from column 'time'");
  }
  const double start = times.values.front();
  const double dt = (times.values.back() - start) / static_cast<double>(count - 1);
  if (!(dt > 0.0)) {
    throw InputError(source, line_location(times.lines.back()),
                     "expected increasing times (dt > 0), got a last time " +
                         number_text(times.values.back()) + " s after a first time " +
                         number_text(start) + " s");
  }
  for (std::size_t i = 1; i < count; ++i) {
    const double expected = start + dt * static_cast<double>(i);
    if (std::abs(times.values[i] - expected) > kTimeStepTolerance * dt) {
      throw InputError(source, line_location(times.lines[i]) + ", column time",
                       "expected uniformly spaced times (dt = " + number_text(dt) +
                           " s from the first and last rows, so " + number_text(expected) +
                           " s here), got " + number_text(times.values[i]) + " s");
    }
  }
  return dt;
}

void check_time_step_agrees(const std::filesystem::path& file, double file_dt,
                            std::optional<double> given_dt, const std::string& where) {
  if (!given_dt)
    return;
  check_given_time_step(file, *given_dt);
  if (std::abs(*given_dt - file_dt) > kTimeStepTolerance * file_dt) {
    throw InputError(file.string(), "dt",
                     "the given time step " + number_text(*given_dt) + " s differs from the " +
                         number_text(file_dt) + " s of " + where);
  }
}

GroundMotion motion_named_after(const std::filesystem::path& file) {
  GroundMotion motion;
  motion.name = file.stem().string();
  return motion;
}

} // namespace

double GroundMotion::peak_acceleration() const {
  double peak = 0.0;
  for (const double value : acceleration)
    peak = std::max(peak, std::abs(value));
  return peak;
}

double millimetres_per_s2(AccelerationUnits units) {
  switch (units) {
  case AccelerationUnits::g:
    return kStandardGravity;
  case AccelerationUnits::m_per_s2:
    return 1000.0;
  case AccelerationUnits::mm_per_s2:
    return 1.0;
  }
  return 1.0;
}

std::string_view units_name(AccelerationUnits units) {
  switch (units) {
  case AccelerationUnits::g:
    return "g";
  case AccelerationUnits::m_per_s2:
    return "m/s^2";
  case AccelerationUnits::mm_per_s2:
    return "mm/s^2";
  }
  return "?";
}

std::optional<AccelerationUnits> acceleration_units_named(std::string_view text) {
  for (const auto units :
       {AccelerationUnits::g, AccelerationUnits::m_per_s2, AccelerationUnits::mm_per_s2}) {
    if (text == units_name(units))
      return units;
  }
  return std::nullopt;
}

AccelerationUnits parse_acceleration_units(std::string_view text, const std::string& source,
                                           const std::string& field) {
  if (const auto units = acceleration_units_named(text))
    return *units;
  throw InputError(source, field,
                   "expected acceleration units \"g\", \"m/s^2\" or \"mm/s^2\", got " +
                       excerpt(text));
}

std::optional<GroundMotionFormat> ground_motion_format_named(std::string_view text) {
  if (text == "auto")
    return GroundMotionFormat::automatic;
  if (text == "at2")
    return GroundMotionFormat::at2;
  if (text == "csv")
    return GroundMotionFormat::csv;
  if (text == "column")
    return GroundMotionFormat::column;
  return std::nullopt;
}

GroundMotion read_peer_at2(const std::filesystem::path& file,
                           std::optional<AccelerationUnits> units_override, double scale) {
  const std::string source = file.string();
  check_readable(file);
  check_scale(file, scale);
  const std::vector<std::string> lines = lines_of_file(file);
  if (std::all_of(lines.begin(), lines.end(),
                  [](const std::string& line) { return trimmed(line).empty(); })) {
    throw InputError(source, "", "the file is empty: expected a PEER AT2 header and values");
  }
  const At2Header header = read_at2_header(file, lines, units_override.has_value());
  const std::optional<AccelerationUnits> units = units_override ? units_override : header.units;
  if (!units) {
    throw InputError(source, "",
                     "the header states no units (expected a line like \"ACCELERATION TIME "
                     "SERIES IN UNITS OF G\"): give the units (g, m/s^2 or mm/s^2)");
  }

  GroundMotion motion = motion_named_after(file);
  motion.dt = header.dt;
  motion.acceleration.reserve(static_cast<std::size_t>(header.npts));
  for (std::size_t i = header.npts_line + 1; i < lines.size(); ++i) {
    if (!trimmed(lines[i]).empty())
      append_values(lines[i], header.field_width, source, i + 1, motion.acceleration);
  }
  const std::string npts_location = line_location(header.npts_line + 1);
  if (motion.acceleration.empty()) {
    throw InputError(source, npts_location,
                     "empty record: expected NPTS=" + std::to_string(header.npts) +
                         " values below the header, found none");
  }
  if (motion.acceleration.size() != static_cast<std::size_t>(header.npts)) {
    throw InputError(source, npts_location,
                     "the header gives NPTS=" + std::to_string(header.npts) +
                         " but the file holds " + std::to_string(motion.acceleration.size()) +
                         " values");
  }
  scale_into_millimetres(motion.acceleration, *units, scale);
  return motion;
}

GroundMotion read_acceleration_csv(const std::filesystem::path& file, AccelerationUnits units,
                                   std::optional<double> dt, double scale) {
  const std::string source = file.string();
  check_readable(file);
  check_scale(file, scale);
  const auto first = first_content_line(file);
  if (!first) {
    throw InputError(source, "",
                     "the file is empty: expected a header `time,accel` or `accel`, or one "
                     "acceleration per line");
  }
  const std::vector<std::string> cells = header_cells(first->second);
  GroundMotion motion = motion_named_after(file);

  if (number_in(cells.front())) { // no header: one value per line
    if (cells.size() > 1) {
      throw InputError(source, line_location(first->first),
                       "expected a header naming the columns (`time,accel`) above several "
                       "columns, or a single column of accelerations");
    }
    if (!dt)
      throw InputError(source, "dt", "a single-column record needs a time step: give dt");
    check_given_time_step(file, *dt);
    motion.dt = *dt;
    motion.acceleration = read_value_per_line(file);
  } else if (std::find(cells.begin(), cells.end(), "time") != cells.end()) {
    const NumericColumn times = read_numeric_column(file, "time");
    const NumericColumn accelerations = read_numeric_column(file, "accel");
    if (times.lines != accelerations.lines) {
      throw InputError(source, "", "the columns 'time' and 'accel' list different rows");
    }
    motion.dt = uniform_time_step(source, times);
    check_time_step_agrees(file, motion.dt, dt, "the column 'time'");
    motion.acceleration = accelerations.values;
  } else {
    if (!dt) {
      throw InputError(source, "dt",
                       "the file has no column 'time': give the time step dt, or add the "
                       "column");
    }
    check_given_time_step(file, *dt);
    motion.dt = *dt;
    motion.acceleration = read_numeric_column(file, "accel").values;
  }
  if (motion.acceleration.empty()) {
    throw InputError(source, "", "empty record: expected at least one acceleration value");
  }
  scale_into_millimetres(motion.acceleration, units, scale);
  return motion;
}

GroundMotion read_acceleration_column(const std::filesystem::path& file, AccelerationUnits units,
                                      double dt, double scale) {
  check_readable(file);
  check_scale(file, scale);
  check_given_time_step(file, dt);
  GroundMotion motion = motion_named_after(file);
  motion.dt = dt;
  motion.acceleration = read_value_per_line(file);
  if (motion.acceleration.empty()) {
    throw InputError(file.string(), "",
                     "empty record: expected one acceleration per line, found none");
  }
  scale_into_millimetres(motion.acceleration, units, scale);
  return motion;
}

GroundMotion load_ground_motion(const std::filesystem::path& file,
                                const GroundMotionOptions& options) {
  const std::string source = file.string();
  GroundMotionFormat format = options.format;
  if (format == GroundMotionFormat::automatic) {
    const std::string extension = upper_case(file.extension().string());
    if (extension == ".AT2") {
      format = GroundMotionFormat::at2;
    } else if (extension == ".CSV") {
      format = GroundMotionFormat::csv;
    } else if (extension == ".REC" || extension == ".TXT") {
      format = GroundMotionFormat::column;
    } else {
      throw InputError(source, "",
                       "cannot tell the record's format from the extension " +
                           excerpt(file.extension().string()) +
                           ": expected .at2, .csv, .rec or .txt (or give the format)");
    }
  }
  const auto required_units = [&]() {
    check_readable(file);
    if (!options.units) {
      throw InputError(source, "units",
                       "the file does not state its units: give them (g, m/s^2 or mm/s^2)");
    }
    return *options.units;
  };

  switch (format) {
  case GroundMotionFormat::at2: {
    GroundMotion motion = read_peer_at2(file, options.units, options.scale);
    check_time_step_agrees(file, motion.dt, options.dt, "the header (DT=)");
    return motion;
  }
  case GroundMotionFormat::csv:
    return read_acceleration_csv(file, required_units(), options.dt, options.scale);
  case GroundMotionFormat::column: {
    const AccelerationUnits units = required_units();
    if (!options.dt) {
      throw InputError(source, "dt", "a single-column record states no time step: give dt (s)");
    }
    return read_acceleration_column(file, units, *options.dt, options.scale);
  }
  case GroundMotionFormat::automatic:
    break;
  }
  throw std::logic_error("load_ground_motion: unresolved format");
}

} // namespace brb::io
