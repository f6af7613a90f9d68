#include "brb/study/pareto_matrix.hpp"

#include "brb/io/json_input.hpp"

#include <cmath>
#include <set>
#include <tuple>

namespace brb::study {
namespace {

namespace fs = std::filesystem;
using io::JsonValue;

constexpr std::size_t kMaxSettings = 1000;
constexpr int kMaxRepeats = 1000;
constexpr int kMaxCoreElements = 4096;
constexpr int kMaxFibers = 1000;

int whole_number(const JsonValue& value, std::string_view meaning, int least, int most) {
  const double number = value.number(meaning);
  if (!(number == std::floor(number) && number >= least && number <= most))
    throw value.error(std::string(meaning) + " must be a whole number from " +
                      std::to_string(least) + " to " + std::to_string(most) + " (got " +
                      io::describe_json_value(value.json()) + ")");
  return static_cast<int>(number);
}

double positive_number(const JsonValue& value, std::string_view meaning) {
  const double number = value.number(meaning);
  if (!(number > 0.0))
    throw value.error(std::string(meaning) + " must be > 0 (got " +
                      io::describe_json_value(value.json()) + ")");
  return number;
}

fs::path existing_file(const JsonValue& value, std::string_view meaning, const fs::path& folder) {
  const std::string name = value.string(meaning);
  if (name.empty())
    throw value.error(std::string(meaning) + " must not be empty");
  const fs::path path = folder / name;
  if (!fs::is_regular_file(path))
    throw value.error(std::string(meaning) + ": no such file: " + path.string());
  return path;
}

SettingFidelity fidelity_named(const JsonValue& value) {
  const std::string text = value.string("fidelity");
  if (text == "truss")
    return SettingFidelity::truss;
  if (text == "full")
    return SettingFidelity::full;
  if (text == "auto")
    return SettingFidelity::automatic;
  throw value.error("fidelity must be \"truss\", \"full\" or \"auto\" (got \"" + text + "\")");
}

ParetoSetting read_setting(const JsonValue& entry, CaseKind kind, const fs::path& folder) {
  entry.expect_object({"label", "fidelity", "core_elements", "fibers", "integration_points", "mode",
                       "max_step", "dt", "repeats", "committed_run"},
                      "a setting: {\"label\": ..., \"fidelity\": ..., ...}");
  ParetoSetting setting;
  const JsonValue label = entry.at("label", "the setting's label (unique in the matrix)");
  setting.label = label.string("setting label");
  if (setting.label.empty())
    throw label.error("the setting label must not be empty");
  setting.fidelity = fidelity_named(entry.at("fidelity", "truss, full or auto"));
  if (const auto value = entry.find("core_elements"))
    setting.core_elements = whole_number(*value, "core elements", 1, kMaxCoreElements);
  if (const auto value = entry.find("fibers")) {
    if (value->expect_array(2, "fiber counts [a, b]") != 2)
      throw value->error("fiber counts must be two whole numbers [a, b]");
    setting.fibers = std::pair{whole_number(value->element(0), "fiber count", 1, kMaxFibers),
                               whole_number(value->element(1), "fiber count", 1, kMaxFibers)};
  }
  if (const auto value = entry.find("integration_points"))
    setting.integration_points = whole_number(*value, "integration points", 2, 6);
  // A component's full brace is the expanded model unless asked condensed (one BRBElement
  // between the outer nodes, analysis/condensed_brace.hpp); a frame's is condensed.
  if (kind == CaseKind::component)
    setting.mode = model::ElementMode::expanded;
  if (const auto value = entry.find("mode")) {
    const std::string text = value->string("element mode");
    if (text == "condensed")
      setting.mode = model::ElementMode::condensed;
    else if (text == "expanded")
      setting.mode = model::ElementMode::expanded;
    else
      throw value->error("mode must be \"condensed\" or \"expanded\" (got \"" + text + "\")");
  }
  if (const auto value = entry.find("max_step")) {
    if (kind != CaseKind::component)
      throw value->error("max_step (dy) applies to component cases only; frames take dt");
    setting.max_step = positive_number(*value, "max_step, dy");
  }
  if (const auto value = entry.find("dt")) {
    if (kind != CaseKind::frame)
      throw value->error("dt (s) applies to frame cases only; components take max_step");
    setting.dt = positive_number(*value, "time step dt, s");
  }
  if (const auto value = entry.find("repeats"))
    setting.repeats = whole_number(*value, "repeats", 1, kMaxRepeats);
  if (const auto value = entry.find("committed_run")) {
    if (kind != CaseKind::frame)
      throw value->error("committed_run (a brb frame run's summary.json) applies to frame cases "
                         "only");
    setting.committed_run =
        existing_file(*value, "summary.json of a committed brb frame run", folder);
  }
  return setting;
}

} // namespace

model::BraceSpec ParetoSetting::applied_to(model::BraceSpec brace) const {
  if (core_elements)
    brace.core_elements = *core_elements;
  if (fibers) {
    brace.core_section.fibers_a = fibers->first;
    brace.core_section.fibers_b = fibers->second;
  }
  if (integration_points)
    brace.integration_points = *integration_points;
  return brace;
}

ParetoCase ParetoCase::quick() const {
  ParetoCase shortened = *this;
  if (quick_duration)
    shortened.duration = *quick_duration;
  if (quick_protocol)
    shortened.protocol = *quick_protocol;
  shortened.repeats = 1;
  for (ParetoSetting& setting : shortened.settings) {
    setting.repeats.reset();
    setting.committed_run.reset(); // a run of the whole window: the quick one is run
  }
  return shortened;
}

std::string to_string(SettingFidelity fidelity) {
  switch (fidelity) {
  case SettingFidelity::truss:
    return "truss";
  case SettingFidelity::full:
    return "full";
  case SettingFidelity::automatic:
    return "auto";
  }
  return "";
}

std::string to_string(CaseKind kind) {
  return kind == CaseKind::frame ? "frame" : "component";
}

std::optional<std::size_t> finest_full_setting(const std::vector<ParetoSetting>& settings) {
  std::optional<std::size_t> finest;
  // Larger is finer: elements, fibers, points, then a smaller step (negated).
  const auto fineness = [](const ParetoSetting& s) {
    const int fibers = s.fibers ? s.fibers->first * s.fibers->second : 0;
    const double step = s.max_step ? *s.max_step : (s.dt ? *s.dt : 0.0);
    return std::tuple{s.core_elements.value_or(0), fibers, s.integration_points.value_or(0), -step};
  };
  for (std::size_t k = 0; k < settings.size(); ++k) {
    if (settings[k].fidelity != SettingFidelity::full)
      continue;
    if (!finest || fineness(settings[*finest]) < fineness(settings[k]))
      finest = k;
  }
  return finest;
}

ParetoCase read_pareto_matrix(const fs::path& file) {
  const nlohmann::json document = io::read_json_file(file);
  const JsonValue root(document, file.string());
  root.expect_object({"name", "kind", "description", "brace", "protocol", "solid", "model",
                      "motion", "scale", "duration", "repeats", "reference", "auto_rule", "quick",
                      "settings"},
                     "a pareto matrix: {\"name\": ..., \"kind\": ..., \"settings\": [...]}");
  ParetoCase study_case;
  study_case.matrix_file = file;
  const fs::path folder = file.parent_path();
  const JsonValue name = root.at("name", "the case's name");
  study_case.name = name.string("case name");
  if (study_case.name.empty())
    throw name.error("the case name must not be empty");
  const JsonValue kind = root.at("kind", "\"component\" or \"frame\"");
  const std::string kind_text = kind.string("case kind");
  if (kind_text == "component")
    study_case.kind = CaseKind::component;
  else if (kind_text == "frame")
    study_case.kind = CaseKind::frame;
  else
    throw kind.error("kind must be \"component\" or \"frame\" (got \"" + kind_text + "\")");
  if (const auto description = root.find("description"))
    study_case.description = description->string("description");

  // The keys of the other kind are errors: a frame case with a protocol is a mistake.
  const bool frame = study_case.kind == CaseKind::frame;
  const std::vector<std::string> other_keys =
      frame ? std::vector<std::string>{"brace", "protocol", "solid"}
            : std::vector<std::string>{"model", "motion", "scale", "duration"};
  for (const std::string& key : other_keys) {
    if (const auto value = root.find(key))
      throw value->error("\"" + key + "\" does not apply to a " + kind_text + " case");
  }
  if (frame) {
    study_case.model = existing_file(root.at("model", "the frame model file"), "model", folder);
    study_case.motion =
        existing_file(root.at("motion", "the ground-motion record file"), "motion", folder);
    if (const auto scale = root.find("scale")) {
      study_case.scale = scale->number("scale factor");
      if (!(study_case.scale != 0.0))
        throw scale->error("scale must be a number other than 0");
    }
    study_case.duration =
        positive_number(root.at("duration", "the window of the record analysed, s"), "duration, s");
  } else {
    study_case.brace = existing_file(root.at("brace", "the brace file"), "brace", folder);
    study_case.protocol =
        existing_file(root.at("protocol", "the protocol file"), "protocol", folder);
    if (const auto solid = root.find("solid"))
      study_case.solid = existing_file(*solid, "summary.json of a brb solid run", folder);
  }
  if (const auto repeats = root.find("repeats"))
    study_case.repeats = whole_number(*repeats, "repeats", 1, kMaxRepeats);
  if (const auto role = root.find("auto_rule")) {
    const std::string text = role->string("role of the case for the auto rule");
    if (text == "derive")
      study_case.auto_rule = AutoRuleRole::derive;
    else if (text == "check")
      study_case.auto_rule = AutoRuleRole::check;
    else
      throw role->error("auto_rule must be \"derive\" or \"check\" (got \"" + text + "\")");
  }
  if (const auto quick = root.find("quick")) {
    if (frame) {
      quick->expect_object({"duration"}, "{\"duration\": s}");
      if (const auto duration = quick->find("duration"))
        study_case.quick_duration = positive_number(*duration, "quick duration, s");
    } else {
      quick->expect_object({"protocol"}, "{\"protocol\": file}");
      if (const auto protocol = quick->find("protocol"))
        study_case.quick_protocol = existing_file(*protocol, "quick protocol", folder);
    }
  }

  const JsonValue settings = root.at("settings", "the list of settings");
  const std::size_t count = settings.expect_array(kMaxSettings, "the list of settings");
  if (count == 0)
    throw settings.error("the matrix needs at least one setting");
  std::set<std::string> labels;
  for (std::size_t k = 0; k < count; ++k) {
    const JsonValue entry = settings.element(k);
    ParetoSetting setting = read_setting(entry, study_case.kind, folder);
    if (!labels.insert(setting.label).second)
      throw entry.error("duplicate setting label \"" + setting.label +
                        "\": each setting needs a unique label");
    study_case.settings.push_back(std::move(setting));
  }
  if (const auto reference = root.find("reference")) {
    const std::string label = reference->string("reference setting label");
    std::optional<std::size_t> found;
    for (std::size_t k = 0; k < study_case.settings.size(); ++k) {
      if (study_case.settings[k].label == label)
        found = k;
    }
    if (!found)
      throw reference->error("reference \"" + label + "\" is not the label of a setting");
    if (study_case.settings[*found].fidelity != SettingFidelity::full)
      throw reference->error("the reference must be a full setting (\"" + label + "\" is " +
                             to_string(study_case.settings[*found].fidelity) + ")");
    study_case.reference = *found;
  } else {
    const auto finest = finest_full_setting(study_case.settings);
    if (!finest)
      throw settings.error("the matrix needs a full setting: the errors are measured against "
                           "its finest full setting (or name a \"reference\")");
    study_case.reference = *finest;
  }
  return study_case;
}

} // namespace brb::study
