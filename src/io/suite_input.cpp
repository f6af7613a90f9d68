#include "brb/io/suite_input.hpp"

#include "brb/io/json_input.hpp"

#include <cmath>
#include <set>

namespace brb::io {
namespace {

constexpr std::size_t kMaxRecords = 100000;

std::optional<SuiteDirection> direction_named(std::string_view text) {
  if (text == "x")
    return SuiteDirection::x;
  if (text == "y")
    return SuiteDirection::y;
  if (text == "z")
    return SuiteDirection::z;
  return std::nullopt;
}

double positive_number(const JsonValue& value, std::string_view meaning) {
  const double number = value.number(meaning);
  if (!(number > 0.0))
    throw value.error(std::string(meaning) + " must be > 0 (got " +
                      describe_json_value(value.json()) + ")");
  return number;
}

SuiteRecord read_record(const JsonValue& entry, const std::filesystem::path& folder) {
  entry.expect_object({"name", "file", "format", "units", "dt", "factor", "direction", "component"},
                      "a record: {\"file\": ..., \"units\": ..., \"dt\": ..., ...}");
  SuiteRecord record;
  const JsonValue file = entry.at("file", "the record file, relative to the suite file");
  const std::string file_name = file.string("record file");
  if (file_name.empty())
    throw file.error("the record file must not be empty");
  record.file = folder / file_name;
  if (!std::filesystem::is_regular_file(record.file))
    throw file.error("no such record file: " + record.file.string());
  record.name = record.file.stem().string();
  if (const auto name = entry.find("name")) {
    record.name = name->string("record name");
    if (record.name.empty())
      throw name->error("the record name must not be empty");
  }
  if (const auto format = entry.find("format")) {
    const std::string text = format->string("record format");
    const auto named = ground_motion_format_named(text);
    if (!named)
      throw format->error("the format must be auto, at2, csv or column (got \"" + text + "\")");
    record.options.format = *named;
  }
  if (const auto units = entry.find("units"))
    record.options.units = parse_acceleration_units(units->string("acceleration units"),
                                                    entry.source(), units->path());
  if (const auto dt = entry.find("dt"))
    record.options.dt = positive_number(*dt, "time step dt, s");
  if (const auto factor = entry.find("factor"))
    record.options.scale = positive_number(*factor, "normalisation factor");
  if (const auto direction = entry.find("direction")) {
    const std::string text = direction->string("ground direction");
    const auto named = direction_named(text);
    if (!named)
      throw direction->error("the direction must be x, y or z (got \"" + text + "\")");
    record.direction = *named;
  }
  if (const auto component = entry.find("component"))
    record.component = component->string("component label");
  return record;
}

} // namespace

GroundMotionSuite read_suite(const std::filesystem::path& file) {
  const nlohmann::json document = read_json_file(file);
  const JsonValue root(document, file.string());
  root.expect_object({"name", "description", "records"},
                     "a suite: {\"name\": ..., \"records\": [...]}");
  GroundMotionSuite suite;
  suite.source = file;
  suite.name = file.stem().string();
  if (const auto name = root.find("name"))
    suite.name = name->string("suite name");
  if (const auto description = root.find("description"))
    suite.description = description->string("description");
  const JsonValue records = root.at("records", "the list of ground-motion records");
  const std::size_t count = records.expect_array(kMaxRecords, "the list of records");
  if (count == 0)
    throw records.error("the suite needs at least one record");
  const std::filesystem::path folder = file.parent_path();
  std::set<std::string> names;
  for (std::size_t k = 0; k < count; ++k) {
    const JsonValue entry = records.element(k);
    SuiteRecord record = read_record(entry, folder);
    if (!names.insert(record.name).second)
      throw entry.error("duplicate record name \"" + record.name +
                        "\": give each record a unique \"name\"");
    suite.records.push_back(std::move(record));
  }
  // Every record is read now: a bad record file stops the IDA before its first run.
  for (std::size_t k = 0; k < suite.records.size(); ++k) {
    const SuiteRecord& record = suite.records[k];
    try {
      suite.motions.push_back(load_ground_motion(record.file, record.options));
    } catch (const InputError& error) {
      throw InputError(file.string(), "/records/" + std::to_string(k),
                       "record \"" + record.name + "\": " + error.what());
    }
    suite.motions.back().name = record.name;
  }
  return suite;
}

} // namespace brb::io
