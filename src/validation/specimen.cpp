#include "brb/validation/specimen.hpp"

#include "brb/io/input_error.hpp"
#include "brb/io/json_input.hpp"
#include "brb/validation/metric_kinds.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>

namespace brb::validation {
namespace {

namespace fs = std::filesystem;
using io::JsonValue;

/// The most refinements a specimen may list, and the largest multiplier (a guard against a
/// typo that would make a run last days).
constexpr std::size_t kMostRefinements = 8;
constexpr int kLargestRefinement = 64;

/// Record units accepted at the edge, with their factor to N or mm.

std::string string_of(const JsonValue& value, std::string_view meaning) {
  return value.string(meaning);
}

bool boolean_of(const JsonValue& value, std::string_view meaning) {
  if (!value.json().is_boolean()) {
    throw value.error(std::string(meaning) + ": expected true or false, got " +
                      io::describe_json_value(value.json()));
  }
  return value.json().get<bool>();
}

int refinement_of(const JsonValue& value) {
  const double number = value.number("refinement (multiplier of every zone's element count)");
  if (!(number >= 1.0 && number <= kLargestRefinement && number == std::floor(number))) {
    throw value.error("a refinement must be a whole number from 1 to " +
                      std::to_string(kLargestRefinement) + " (got " +
                      io::describe_json_value(value.json()) + ")");
  }
  return static_cast<int>(number);
}

std::vector<int> read_refinements(const JsonValue& list) {
  const std::size_t count =
      list.expect_array(kMostRefinements, "refinements: a list of multipliers, e.g. [1, 2, 4]");
  if (count == 0)
    throw list.error("refinements: give at least one multiplier, e.g. [1]");
  std::vector<int> refinements;
  for (std::size_t i = 0; i < count; ++i) {
    const int refinement = refinement_of(list.element(i));
    if (std::find(refinements.begin(), refinements.end(), refinement) != refinements.end())
      throw list.element(i).error("refinement " + std::to_string(refinement) + " listed twice");
    refinements.push_back(refinement);
  }
  return refinements;
}

/// A file named in metrics.json, relative to the specimen's folder; it must exist.
fs::path specimen_file(const JsonValue& value, std::string_view meaning,
                       const fs::path& directory) {
  const std::string name = string_of(value, meaning);
  if (name.empty())
    throw value.error(std::string(meaning) + ": must name a file");
  const fs::path file = directory / name;
  if (!fs::is_regular_file(file))
    throw value.error(std::string(meaning) + ": no such file: " + file.string());
  return file;
}

Tolerance read_tolerance(const JsonValue& value) {
  value.expect_object({"relative", "absolute"},
                      "tolerance: {\"relative\": fraction} or {\"absolute\": value}");
  const std::optional<JsonValue> relative = value.find("relative");
  const std::optional<JsonValue> absolute = value.find("absolute");
  if (relative.has_value() == absolute.has_value()) {
    throw value.error("tolerance: give exactly one of \"relative\" (a fraction of the "
                      "reference) and \"absolute\" (in the metric's unit)");
  }
  const JsonValue& given = relative ? *relative : *absolute;
  const double number = given.number("tolerance");
  if (!(number >= 0.0))
    throw given.error("tolerance must be >= 0 (got " + io::describe_json_value(given.json()) + ")");
  return {relative ? Tolerance::Kind::relative : Tolerance::Kind::absolute, number};
}

/// The common keys of a metric object; a kind adds its own (MetricKind::keys).
constexpr std::array<std::string_view, 10> kCommonMetricKeys{
    "name",    "kind",     "reference", "tolerance", "at_least",
    "at_most", "expected", "unit",      "source",    "note"};

MetricSpec read_metric(const JsonValue& value, std::set<std::string>& names) {
  if (!value.json().is_object())
    throw value.error("a metric must be an object {\"name\": ..., \"kind\": ..., ...}");
  const JsonValue kind_value = value.at("kind", "the metric's kind, one of " + metric_kind_names());
  const std::string kind_name = string_of(kind_value, "kind");
  const MetricKind* kind = find_metric_kind(kind_name);
  if (kind == nullptr) {
    throw kind_value.error("unknown metric kind \"" + kind_name +
                           "\"; known kinds: " + metric_kind_names());
  }
  // Allowed keys: the common ones and the kind's. JsonValue::expect_object wants an
  // initializer list; check the unknown keys here instead, with the same message form.
  for (const auto& [key, member] : value.json().items()) {
    const bool common = std::find(kCommonMetricKeys.begin(), kCommonMetricKeys.end(), key) !=
                        kCommonMetricKeys.end();
    const bool own = std::find(kind->keys.begin(), kind->keys.end(), key) != kind->keys.end();
    if (!common && !own) {
      std::string allowed;
      for (const std::string_view name : kCommonMetricKeys)
        allowed += (allowed.empty() ? "" : ", ") + std::string(name);
      for (const std::string_view name : kind->keys)
        allowed += ", " + std::string(name);
      throw JsonValue(member, value.source(), io::json_pointer_append(value.path(), key))
          .error("unknown key for a metric of kind \"" + kind_name +
                 "\"; allowed keys are: " + allowed);
    }
  }
  MetricSpec metric;
  metric.kind = kind_name;
  metric.parameters = value.json();
  const JsonValue name = value.at("name", "the metric's name, unique in the file");
  metric.name = string_of(name, "name");
  if (metric.name.empty())
    throw name.error("the metric's name must not be empty");
  if (!names.insert(metric.name).second)
    throw name.error("metric \"" + metric.name + "\" is defined twice");
  kind->check(value);

  if (const auto unit = value.find("unit"))
    metric.unit = string_of(*unit, "unit of the metric's value");
  if (const auto source = value.find("source"))
    metric.source = string_of(*source, "source of the reference");
  if (const auto note = value.find("note"))
    string_of(*note, "note");

  const std::optional<JsonValue> reference = value.find("reference");
  const std::optional<JsonValue> tolerance = value.find("tolerance");
  const std::optional<JsonValue> at_least = value.find("at_least");
  const std::optional<JsonValue> at_most = value.find("at_most");
  const std::optional<JsonValue> expected = value.find("expected");
  if (kind->is_flag) {
    for (const auto* judged : {&reference, &tolerance, &at_least, &at_most}) {
      if (judged->has_value())
        throw(*judged)->error("a flag is checked by \"expected\" (true or false) only");
    }
    if (!expected)
      throw value.error("missing \"expected\": a flag metric says whether the flag should be "
                        "raised (true) or not (false)");
    metric.expected = boolean_of(*expected, "expected");
    metric.unit = "-";
    return metric;
  }
  if (expected)
    throw expected->error("\"expected\" is for metrics of kind \"flag\" only");
  if (reference.has_value() != tolerance.has_value()) {
    throw(reference ? *reference : *tolerance)
        .error("\"reference\" and \"tolerance\" go together: give both or neither");
  }
  if ((reference || tolerance) && (at_least || at_most)) {
    throw(at_least ? *at_least : *at_most)
        .error("give either a reference with a tolerance or bounds (at_least, at_most), not both");
  }
  if (reference) {
    metric.reference = reference->number("reference value");
    metric.tolerance = read_tolerance(*tolerance);
  }
  if (at_least)
    metric.at_least = at_least->number("lower bound at_least");
  if (at_most)
    metric.at_most = at_most->number("upper bound at_most");
  if (metric.at_least && metric.at_most && *metric.at_least > *metric.at_most)
    throw at_most->error("at_most must be >= at_least");
  return metric;
}

ReferenceType reference_type(const JsonValue& object) {
  const std::optional<JsonValue> type = object.find("type");
  if (!type)
    return ReferenceType::lab_record;
  const std::string name = string_of(*type, "reference type");
  for (const ReferenceType known :
       {ReferenceType::lab_record, ReferenceType::solid_run, ReferenceType::solver_csv}) {
    if (name == to_string(known))
      return known;
  }
  throw type->error("unknown reference type \"" + name +
                    "\": expected \"lab_record\" (a measured record, the default), "
                    "\"solid_run\" (a `brb solid` output directory) or \"solver_csv\" (a "
                    "force-deformation CSV of another 3D solver)");
}

FailureEvent read_failure(const JsonValue& value) {
  value.expect_object({"failure_mode", "cycle"},
                      "the reference's failure {\"failure_mode\": ..., \"cycle\": k}");
  const JsonValue mode_value =
      value.at("failure_mode", "the failure mode, one of " + failure_mode_names());
  const std::string name = string_of(mode_value, "failure mode");
  const std::optional<FailureMode> mode = failure_mode_named(name);
  if (!mode) {
    throw mode_value.error("unknown failure mode \"" + name + "\": expected one of " +
                           failure_mode_names());
  }
  FailureEvent event{*mode, 0};
  const std::optional<JsonValue> cycle = value.find("cycle");
  if (*mode == FailureMode::none) {
    if (cycle)
      throw cycle->error("a reference that does not fail (\"none\") has no failure cycle");
    return event;
  }
  if (!cycle)
    throw value.error("missing \"cycle\": the protocol cycle (1-based) the failure happens in");
  const double number = cycle->number("failure cycle");
  if (!(number >= 1.0 && number == std::floor(number) && number < 1e9)) {
    throw cycle->error("the failure cycle must be a whole number >= 1 (got " +
                       io::describe_json_value(cycle->json()) + ")");
  }
  event.cycle = static_cast<int>(number);
  return event;
}

/// A path of metrics.json: "shared:REST" against the shared directory, a relative one against
/// the specimen's folder.
fs::path resolved_path(const std::string& written, const fs::path& directory,
                       const fs::path& shared_directory) {
  const std::string_view prefix = shared_prefix;
  if (written.starts_with(prefix))
    return shared_directory / written.substr(prefix.size());
  return fs::path(written).is_absolute() ? fs::path(written) : directory / written;
}

/// A reference read by io/force_record.hpp's reader (a lab record, a solver's CSV): the keys
/// that reader does not know (type, failure, columns/time) are checked here and left out.
void read_record_file(const JsonValue& value, const fs::path& directory,
                      const fs::path& shared_directory, RecordReference& record) {
  nlohmann::json plain = value.json();
  plain.erase("type");
  plain.erase("failure");
  if (record.type == ReferenceType::solver_csv) {
    const JsonValue columns = value.at(
        "columns", "the column names {\"deformation\": ..., \"force\": ..., \"time\": ...}");
    columns.expect_object({"deformation", "force", "time"},
                          "the column names {\"deformation\", \"force\", \"time\" (optional, "
                          "not used)}");
    if (const auto time = columns.find("time")) {
      record.time_column = string_of(*time, "time column name");
      plain["columns"].erase("time");
    }
  }
  const JsonValue plain_value(plain, value.source(), value.path());
  record.source = io::read_force_record_reference(plain_value, directory, shared_directory);
  record.written = string_of(value.at("file", "the reference's CSV file"), "file");
  if (!fs::is_regular_file(record.source.file))
    throw value.at("file", "").error("no such file: " + record.source.file.string());
}

RecordReference read_record(const JsonValue& value, const fs::path& directory,
                            const fs::path& shared_directory) {
  if (!value.json().is_object()) {
    throw value.error("the reference must be an object {\"type\": \"lab_record\" | "
                      "\"solid_run\" | \"solver_csv\", ...}");
  }
  RecordReference record;
  record.type = reference_type(value);
  switch (record.type) {
  case ReferenceType::lab_record:
    value.expect_object({"type", "file", "columns", "units", "exclude_rows", "failure"},
                        "a lab record reference");
    read_record_file(value, directory, shared_directory, record);
    break;
  case ReferenceType::solver_csv:
    value.expect_object({"type", "file", "columns", "units", "exclude_rows", "failure"},
                        "a solver CSV reference");
    read_record_file(value, directory, shared_directory, record);
    break;
  case ReferenceType::solid_run: {
    value.expect_object({"type", "directory", "failure"},
                        "a `brb solid` run reference {\"type\": \"solid_run\", "
                        "\"directory\": ..., \"failure\": ...}");
    const JsonValue written =
        value.at("directory", "the output directory of the `brb solid` run (--out)");
    record.written = string_of(written, "directory");
    const fs::path run = resolved_path(record.written, directory, shared_directory);
    if (!fs::is_directory(run))
      throw written.error("no such directory: " + run.string());
    // The `brb cyclic` contract of hysteresis.csv (README): columns deformation (mm) and
    // force (N), which `brb solid` writes too.
    record.source.file = run / "hysteresis.csv";
    record.source.format.deformation_column = "deformation";
    record.source.format.force_column = "force";
    if (!fs::is_regular_file(record.source.file))
      throw written.error("the run directory has no hysteresis.csv: " +
                          record.source.file.string());
    // its run time, when the run wrote one (a summary is optional: the failure is stated)
    const fs::path summary = run / "summary.json";
    if (fs::is_regular_file(summary)) {
      const nlohmann::json document = io::read_json_file(summary);
      const auto number = [&](const char* pointer) -> std::optional<double> {
        const nlohmann::json::json_pointer path(pointer);
        if (document.contains(path) && document.at(path).is_number())
          return document.at(path).get<double>();
        return std::nullopt;
      };
      record.run_seconds = number("/solid/run_seconds");
      record.max_kinetic_over_internal = number("/solid/max_kinetic_over_internal");
      record.max_hourglass_over_internal = number("/solid/max_hourglass_over_internal");
    }
    break;
  }
  }
  if (const auto failure = value.find("failure"))
    record.failure = read_failure(*failure);
  return record;
}

void read_comparison(const JsonValue& value, RecordReference& record) {
  value.expect_object(
      {"record_row_column", "reversal_threshold_dy", "energy_floor_fraction", "path_tolerance_dy"},
      "comparison: {\"record_row_column\", \"reversal_threshold_dy\", "
      "\"energy_floor_fraction\", \"path_tolerance_dy\"}");
  const bool lab_record = record.type == ReferenceType::lab_record;
  if (const auto column = value.find("record_row_column")) {
    if (!lab_record) {
      throw column->error("record_row_column is for a lab_record reference; a " +
                          to_string(record.type) + " is matched along the deformation path");
    }
    record.record_row_column = string_of(*column, "record_row_column");
  }
  if (const auto threshold = value.find("reversal_threshold_dy")) {
    record.reversal_threshold_dy = threshold->number("reversal threshold in dy");
    if (!(record.reversal_threshold_dy >= 0.0))
      throw threshold->error("the reversal threshold must be >= 0 dy");
  }
  if (const auto floor = value.find("energy_floor_fraction")) {
    record.energy_floor_fraction = floor->number("energy floor, a fraction");
    if (!(record.energy_floor_fraction >= 0.0 && record.energy_floor_fraction < 1.0))
      throw floor->error("the energy floor must be a fraction in [0, 1)");
  }
  if (const auto tolerance = value.find("path_tolerance_dy")) {
    if (lab_record) {
      throw tolerance->error("path_tolerance_dy is for solid_run and solver_csv references; a "
                             "lab record is matched by its rows (record_row_column)");
    }
    record.path_tolerance_dy = tolerance->number("path tolerance in dy");
    if (!(record.path_tolerance_dy > 0.0))
      throw tolerance->error("the path tolerance must be > 0 dy");
  }
}

} // namespace

RecordReference read_record_reference(const JsonValue& value, const fs::path& directory,
                                      const fs::path& shared_directory) {
  return read_record(value, directory, shared_directory);
}

std::string to_string(ReferenceType type) {
  switch (type) {
  case ReferenceType::lab_record:
    return "lab_record";
  case ReferenceType::solid_run:
    return "solid_run";
  case ReferenceType::solver_csv:
    break;
  }
  return "solver_csv";
}

Specimen read_specimen(const fs::path& directory, const fs::path& shared_directory) {
  Specimen specimen;
  specimen.directory = directory;
  specimen.metrics_file = directory / metrics_file_name;
  const nlohmann::json document = io::read_json_file(specimen.metrics_file);
  const JsonValue root(document, specimen.metrics_file.string());
  root.expect_object({"id", "title", "source", "brace", "protocol", "refinements", "solver",
                      "reference", "comparison", "role", "calibrated_on", "notes", "metrics"},
                     "a specimen's metrics file (an object)");

  const JsonValue id = root.at("id", "the specimen's id, the name of its folder");
  specimen.id = string_of(id, "id");
  const std::string folder =
      directory.filename().empty() ? directory.parent_path().filename() : directory.filename();
  if (specimen.id != folder) {
    throw id.error("the id must be the folder's name \"" + folder + "\" (got \"" + specimen.id +
                   "\")");
  }
  specimen.title = string_of(root.at("title", "a one-line title"), "title");
  specimen.source = string_of(root.at("source", "where the specimen's data come from"), "source");
  specimen.brace_file =
      specimen_file(root.at("brace", "the brace file, e.g. \"brace.json\""), "brace", directory);
  specimen.protocol_file =
      specimen_file(root.at("protocol", "the protocol file, \"protocol.json\" or \"protocol.csv\""),
                    "protocol", directory);
  const std::string extension = specimen.protocol_file.extension().string();
  if (extension != ".json" && extension != ".csv") {
    throw root.at("protocol", "")
        .error("the protocol must be a .json protocol file or a .csv "
               "deformation history (got \"" +
               specimen.protocol_file.filename().string() + "\")");
  }
  specimen.refinements = read_refinements(root.at("refinements", "e.g. [1, 2, 4]"));
  if (const auto solver = root.find("solver")) {
    solver->expect_object({"balance_tolerance"}, "the solver's settings for this specimen");
    if (const auto tolerance = solver->find("balance_tolerance")) {
      specimen.balance_tolerance =
          tolerance->number("the balance control's tolerance (a fraction of the gross work)");
      if (!(specimen.balance_tolerance >= 0.0 && specimen.balance_tolerance < 1.0))
        throw tolerance->error("balance_tolerance must be in [0, 1) (0: off)");
    }
  }
  if (const auto record = root.find("reference"))
    specimen.record = read_record(*record, directory, shared_directory);
  if (const auto comparison = root.find("comparison")) {
    if (!specimen.record)
      throw comparison->error("a comparison needs a reference");
    read_comparison(*comparison, *specimen.record);
  }
  if (const auto role = root.find("role")) {
    specimen.role = string_of(*role, "role");
    if (specimen.role != "calibration" && specimen.role != "prediction")
      throw role->error("role must be \"calibration\" or \"prediction\"");
  }
  if (const auto calibrated_on = root.find("calibrated_on"))
    specimen.calibrated_on = string_of(*calibrated_on, "calibrated_on");
  if (const auto notes = root.find("notes")) {
    const std::size_t count = notes->expect_array(1000, "notes: a list of strings");
    for (std::size_t i = 0; i < count; ++i)
      specimen.notes.push_back(string_of(notes->element(i), "note"));
  }
  const JsonValue metrics = root.at("metrics", "the list of metrics");
  const std::size_t count = metrics.expect_array(1000, "metrics: a list of metric objects");
  std::set<std::string> names;
  for (std::size_t i = 0; i < count; ++i) {
    specimen.metrics.push_back(read_metric(metrics.element(i), names));
    if (specimen.metrics.back().kind == "record_failure_mode" &&
        !(specimen.record && specimen.record->failure)) {
      throw metrics.element(i).error(
          "a record_failure_mode metric needs the reference's \"failure\": "
          "{\"failure_mode\": " +
          failure_mode_names() + ", \"cycle\": k}");
    }
  }
  return specimen;
}

std::vector<fs::path> find_specimen_directories(const fs::path& validation_directory) {
  if (!fs::is_directory(validation_directory)) {
    throw io::InputError(validation_directory.string(), "",
                         "not a directory: expected the validation folder (e.g. validation/)");
  }
  std::vector<fs::path> directories;
  for (const fs::directory_entry& entry : fs::directory_iterator(validation_directory)) {
    if (entry.is_directory() && fs::is_regular_file(entry.path() / metrics_file_name))
      directories.push_back(entry.path());
  }
  std::sort(directories.begin(), directories.end());
  return directories;
}

std::vector<int> parse_refinement_list(const std::string& text) {
  std::vector<int> refinements;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    std::size_t used = 0;
    int value = 0;
    try {
      value = std::stoi(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() || value < 1 || value > kLargestRefinement) {
      throw std::invalid_argument("expected whole numbers from 1 to " +
                                  std::to_string(kLargestRefinement) +
                                  " separated by commas, e.g. 1,2,4 (got \"" + text + "\")");
    }
    if (std::find(refinements.begin(), refinements.end(), value) == refinements.end())
      refinements.push_back(value);
  }
  if (refinements.empty())
    throw std::invalid_argument("expected at least one refinement, e.g. 1,2,4");
  return refinements;
}

} // namespace brb::validation
