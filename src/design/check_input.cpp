#include "brb/design/check_input.hpp"

#include "brb/io/brace_input.hpp"
#include "brb/io/frame_input.hpp"
#include "brb/io/json_input.hpp"
#include "brb/io/material_input.hpp"
#include "brb/material/parameter_error.hpp"
#include "brb/model/brace_model.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <variant>

namespace brb::design {
namespace {

using io::describe_json_value;
using io::JsonValue;

/// A number of `object`'s member `key` that must satisfy `valid`; `expected` completes
/// "must be ..." in the message.
double checked_number(const JsonValue& value, std::string_view meaning, bool valid,
                      std::string_view expected) {
  if (!valid) {
    throw value.error(std::string(meaning) + " must be " + std::string(expected) + " (got " +
                      describe_json_value(value.json()) + ")");
  }
  return value.json().get<double>();
}

double positive(const JsonValue& value, std::string_view meaning, std::string_view unit) {
  const double number = value.number(meaning);
  return checked_number(value, meaning, number > 0.0, "> 0" + std::string(unit));
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names)
    text += (text.empty() ? "" : ", ") + name;
  return text;
}

StoryGeometry read_story(const JsonValue& object) {
  object.expect_object({"height", "bay_width", "configuration"},
                       "the story the brace sits in: {\"height\": mm, \"bay_width\": mm, "
                       "\"configuration\": \"diagonal\" | \"chevron\"}");
  StoryGeometry story;
  story.story_height = positive(object.at("height", "story height, mm"), "story height", " mm");
  story.bay_width = positive(object.at("bay_width", "bay width, mm"), "bay width", " mm");
  if (const auto configuration = object.find("configuration")) {
    const std::string text = configuration->string("brace configuration");
    if (text == "diagonal") {
      story.configuration = BraceConfiguration::diagonal;
    } else if (text == "chevron") {
      story.configuration = BraceConfiguration::chevron;
    } else {
      throw configuration->error("unknown brace configuration \"" + text +
                                 "\"; expected \"diagonal\" or \"chevron\"");
    }
  }
  return story;
}

DesignDriftSpec read_design_drift(const JsonValue& object) {
  object.expect_object({"ratio", "drift", "elastic_drift", "Cd", "Ie"},
                       "the design story drift: {\"ratio\": drift / story height}, "
                       "{\"drift\": mm}, or {\"elastic_drift\": delta_xe in mm, \"Cd\": ..., "
                       "\"Ie\": ...}");
  const auto ratio = object.find("ratio");
  const auto drift = object.find("drift");
  const auto elastic = object.find("elastic_drift");
  const int given = (ratio ? 1 : 0) + (drift ? 1 : 0) + (elastic ? 1 : 0);
  if (given != 1) {
    throw object.error("give exactly one of \"ratio\", \"drift\" (mm) and \"elastic_drift\" "
                       "(mm, with \"Cd\" and \"Ie\")");
  }
  DesignDriftSpec spec;
  const auto non_negative = [](const JsonValue& value, std::string_view meaning,
                               std::string_view unit) {
    const double number = value.number(meaning);
    return checked_number(value, meaning, number >= 0.0,
                          ">= 0" + std::string(unit) + " (a drift is a magnitude)");
  };
  if (ratio) {
    spec.source = DriftSource::ratio;
    spec.value = non_negative(*ratio, "design story drift ratio", "");
    if (spec.value >= 1.0) {
      throw ratio->error("design story drift ratio must be < 1 (got " +
                         describe_json_value(ratio->json()) + "; 0.02 is 2 % of the story height)");
    }
  } else if (drift) {
    spec.source = DriftSource::drift;
    spec.value = non_negative(*drift, "design story drift", " mm");
  } else {
    spec.source = DriftSource::elastic;
    spec.value = non_negative(*elastic, "elastic story drift delta_xe", " mm");
    spec.Cd = positive(object.at("Cd", "deflection amplification factor Cd (ASCE 7 table 12.2-1)"),
                       "Cd", "");
    const JsonValue ie = object.at("Ie", "importance factor Ie (ASCE 7 table 1.5-2)");
    const double ie_value = ie.number("Ie");
    spec.Ie =
        checked_number(ie, "importance factor Ie", ie_value >= 1.0, ">= 1 (ASCE 7: 1.0 to 1.5)");
  }
  if (!elastic) {
    for (const char* key : {"Cd", "Ie"}) {
      if (const auto extra = object.find(key))
        throw extra->error(std::string(key) + " is only used with \"elastic_drift\"");
    }
  }
  return spec;
}

void read_fysc(const JsonValue& object, CheckSpec& check) {
  object.expect_object({"specified", "measured"},
                       "the core's yield stress Fysc, MPa: {\"specified\": ..., \"measured\": "
                       "...} (at least one)");
  if (const auto specified = object.find("specified"))
    check.fysc_specified = positive(*specified, "specified Fysc", " MPa");
  if (const auto measured = object.find("measured"))
    check.fysc_measured = positive(*measured, "measured Fysc", " MPa");
  if (!check.fysc_specified && !check.fysc_measured)
    throw object.error("give \"specified\" or \"measured\" Fysc (MPa), or leave out \"Fysc\"");
}

} // namespace

double CheckSpec::design_story_drift() const {
  switch (design_drift.source) {
  case DriftSource::ratio:
    return design_drift.value * story.story_height;
  case DriftSource::drift:
    return design_drift.value;
  case DriftSource::elastic:
    // ASCE 7-16 (12.8-15): delta_x = Cd delta_xe / Ie.
    return design_drift.Cd * design_drift.value / design_drift.Ie;
  }
  return 0.0;
}

double CheckSpec::beta_limit() const {
  return beta_limit_override.value_or(edition.beta_limit);
}

CheckSpec parse_check(std::string_view json_text, const std::string& source,
                      const std::filesystem::path& base_directory) {
  const nlohmann::json document = io::parse_json(json_text, source);
  const JsonValue root(document, source);
  root.expect_object({"name", "units", "brace", "frame", "story", "design_drift", "Fysc", "Ry",
                      "edition", "beta_limit", "max_step", "drift_capacity"},
                     "a check file object");
  CheckSpec check;
  if (const auto name = root.find("name"))
    check.name = name->string("check name");
  if (const auto units = root.find("units")) {
    if (units->string("units") != "mm")
      throw units->error("unsupported units \"" + units->json().get<std::string>() +
                         "\"; only \"mm\" (N, mm, MPa) is supported");
  }

  const auto frame = root.find("frame");
  const auto brace = root.find("brace");
  const auto story = root.find("story");
  if (frame) {
    if (brace)
      throw brace->error("\"brace\" is not used with \"frame\": the frame element's brace is "
                         "checked; give one of them");
    if (story)
      throw story->error("\"story\" is not used with \"frame\": the story comes from the frame "
                         "model; give one of them");
    frame->expect_object({"model", "brace"},
                         "the frame model and the brace: {\"model\": frame file, \"brace\": id "
                         "of a brb element}");
    const JsonValue model_value = frame->at("model", "frame model file (path relative to the "
                                                     "check file)");
    const std::filesystem::path model_file =
        base_directory / model_value.string("frame model file");
    const model::FrameSpec frame_spec = io::read_frame(model_file);
    const JsonValue id_value = frame->at("brace", "id of the brb element to check");
    const double id = id_value.number("brace element id");
    if (id != std::floor(id)) {
      throw id_value.error("brace element id must be a whole number (got " +
                           describe_json_value(id_value.json()) + ")");
    }
    std::string brb_ids;
    const model::FrameElementSpec* found = nullptr;
    for (const model::FrameElementSpec& element : frame_spec.elements) {
      if (!std::holds_alternative<model::BraceElementSpec>(element.kind))
        continue;
      brb_ids += (brb_ids.empty() ? "" : ", ") + std::to_string(element.id);
      if (element.id == static_cast<int>(id))
        found = &element;
    }
    if (found == nullptr) {
      throw id_value.error("brace id " + describe_json_value(id_value.json()) +
                           " is not a brb element of the frame " + model_file.string() +
                           "; expected one of: " + (brb_ids.empty() ? "(none)" : brb_ids));
    }
    try {
      check.frame_brace = frame_brace_geometry(frame_spec, found->id);
    } catch (const std::invalid_argument& error) {
      throw id_value.error(std::string(error.what()) + " in " + model_file.string() +
                           "; expected a brace between two levels of a story");
    }
    check.story = check.frame_brace->story_geometry();
    check.brace = std::get<model::BraceElementSpec>(found->kind).brace;
    check.frame_source = model_file.string();
    check.brace_source = model_file.string() + " element " + std::to_string(found->id);
  } else {
    if (!brace)
      throw root.error("missing \"brace\" (a brace file) or \"frame\" ({\"model\", \"brace\"}): "
                       "the check needs the brace");
    const std::filesystem::path brace_file = base_directory / brace->string("brace file");
    check.brace = io::read_brace(brace_file);
    check.brace_source = brace_file.string();
    try {
      // Geometry the schema cannot see (e.g. a tube too small for the core and its gaps).
      (void)model::build_brace_model(check.brace);
    } catch (const ParameterError& error) {
      throw io::input_error_from(
          error, io::ParameterSource{brace_file.string(), io::read_json_file(brace_file)});
    }
    if (!story)
      throw root.error("missing \"story\" ({\"height\", \"bay_width\", \"configuration\"}): "
                       "the kinematics need the story (or give \"frame\")");
    check.story = read_story(*story);
  }
  // The qualification test runs the full model, whatever the brace file's fidelity says.
  check.brace.element.fidelity = model::Fidelity::full;

  check.design_drift = read_design_drift(
      root.at("design_drift", "the design story drift: {\"ratio\"}, "
                              "{\"drift\"} or {\"elastic_drift\", \"Cd\", \"Ie\"}"));
  if (const auto fysc = root.find("Fysc"))
    read_fysc(*fysc, check);
  if (!check.fysc_specified && !check.fysc_measured)
    check.fysc_measured = check.brace.steel.yield_stress;
  if (const auto ry = root.find("Ry")) {
    const double value = ry->number("Ry");
    check.Ry = checked_number(*ry, "Ry (expected to specified minimum yield stress)", value >= 1.0,
                              ">= 1 (AISC 341 A3.2; 1.0 with a measured Fysc)");
  }
  Edition edition = Edition::aisc341_16;
  if (const auto value = root.find("edition")) {
    const std::string text = value->string("edition of AISC 341");
    const std::optional<Edition> known = edition_from_string(text);
    if (!known)
      throw value->error("unknown edition \"" + text + "\"; expected one of " +
                         joined(edition_names()));
    edition = *known;
  }
  check.edition = edition_parameters(edition);
  if (const auto beta = root.find("beta_limit")) {
    const double value = beta->number("beta limit");
    check.beta_limit_override =
        checked_number(*beta, "beta limit (largest Pmax / Tmax)", value >= 1.0, ">= 1");
  }
  if (const auto step = root.find("max_step")) {
    // At most 0.1 Delta_by: measured on a small restrained brace (README "brb check"), steps
    // of 0.2 Delta_by crushed the mortar at the design drift where 0.1 Delta_by held it to
    // 4.5 % drift, and 0.25 Delta_by sent the Girona D3 brace through the regularised solver
    // at every step; coarser steps are not a cheaper answer but a different one.
    const double value = step->number("max_step");
    check.max_step =
        checked_number(*step, "max_step (multiples of Delta_by)", value > 0.0 && value <= 0.1,
                       "in (0, 0.1] Delta_by (coarser steps change the answer)");
  }
  if (const auto capacity = root.find("drift_capacity")) {
    capacity->expect_object({"resolution", "upper"},
                            "the drift-capacity search: {\"resolution\": drift ratio, "
                            "\"upper\": drift ratio}");
    DriftCapacitySpec spec;
    if (const auto resolution = capacity->find("resolution")) {
      const double value = resolution->number("resolution");
      spec.resolution = checked_number(*resolution, "drift-capacity resolution (drift ratio)",
                                       value > 0.0 && value < 0.1, "in (0, 0.1)");
    }
    if (const auto upper = capacity->find("upper")) {
      const double value = upper->number("upper");
      spec.upper =
          checked_number(*upper, "upper end of the drift-capacity search (drift ratio)",
                         value > check.edition.minimum_drift_ratio && value < 1.0,
                         "above the minimum drift ratio " +
                             std::to_string(check.edition.minimum_drift_ratio) + " and < 1");
    }
    check.drift_capacity = spec;
  }
  return check;
}

CheckSpec read_check(const std::filesystem::path& file) {
  CheckSpec check = parse_check(io::read_text_file(file), file.string(), file.parent_path());
  if (check.name.empty())
    check.name = file.stem().string();
  return check;
}

} // namespace brb::design
