#include "brb/io/brace_input.hpp"

#include "brb/io/json_input.hpp"
#include "brb/io/material_input.hpp"
#include "brb/material/parameter_error.hpp"
#include "brb/solid/brace_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace brb::io {
namespace {

using model::SectionShape;
using model::SectionSpec;

double positive_length(const JsonValue& object, std::string_view key, std::string_view meaning) {
  const JsonValue value = object.at(key, meaning);
  const double number = value.number(meaning);
  if (!(number > 0.0)) {
    throw value.error(std::string(meaning) + " must be > 0 mm (got " +
                      describe_json_value(value.json()) + ")");
  }
  return number;
}

int positive_count(const JsonValue& value, std::string_view meaning) {
  const double number = value.number(meaning);
  if (!(number >= 1.0) || number != std::floor(number) || number > 100000.0) {
    throw value.error(std::string(meaning) + " must be a whole number >= 1 (got " +
                      describe_json_value(value.json()) + ")");
  }
  return static_cast<int>(number);
}

/// A string option: the value paired with the text found, or an error listing the choices.
template <class Value>
Value one_of(const JsonValue& option, std::string_view meaning,
             std::span<const std::pair<std::string_view, Value>> choices) {
  const std::string text = option.string(meaning);
  std::string names;
  for (const auto& [name, value] : choices) {
    if (text == name)
      return value;
    names += (names.empty() ? "" : ", ") + std::string(name);
  }
  throw option.error("unknown " + std::string(meaning) + " \"" + text + "\"; expected one of " +
                     names);
}

template <class Value>
Value one_of(const JsonValue& option, std::string_view meaning,
             std::initializer_list<std::pair<std::string_view, Value>> choices) {
  return one_of(
      option, meaning,
      std::span<const std::pair<std::string_view, Value>>(choices.begin(), choices.size()));
}

SectionSpec read_section(const JsonValue& object) {
  object.expect_object({"shape", "width", "depth", "diameter", "thickness", "wall", "fibers"},
                       "a section object {\"shape\": ..., dimensions in mm, \"fibers\": [a, b]}");
  const JsonValue shape_value = object.at(
      "shape", "section shape: rectangle, circle, cruciform, rectangular_tube or circular_tube");
  const std::string shape = shape_value.string("section shape");
  SectionSpec section;
  std::vector<std::string_view> dimensions;
  std::pair<int, int> default_fibers;
  if (shape == "rectangle") {
    section.shape = SectionShape::rectangle;
    dimensions = {"width", "depth"};
    default_fibers = {8, 8};
  } else if (shape == "circle") {
    section.shape = SectionShape::circle;
    dimensions = {"diameter"};
    default_fibers = {4, 16};
  } else if (shape == "cruciform") {
    section.shape = SectionShape::cruciform;
    dimensions = {"width", "depth", "thickness"};
    default_fibers = {8, 4};
  } else if (shape == "rectangular_tube") {
    section.shape = SectionShape::rectangular_tube;
    dimensions = {"width", "depth", "wall"};
    default_fibers = {8, 2};
  } else if (shape == "circular_tube") {
    section.shape = SectionShape::circular_tube;
    dimensions = {"diameter", "wall"};
    default_fibers = {2, 24};
  } else {
    throw shape_value.error("unknown section shape \"" + shape +
                            "\"; expected rectangle, circle, cruciform, rectangular_tube or "
                            "circular_tube");
  }
  for (const std::string_view key : {"width", "depth", "diameter", "thickness", "wall"}) {
    const bool used = std::find(dimensions.begin(), dimensions.end(), key) != dimensions.end();
    if (const auto given = object.find(key); given && !used) {
      throw given->error("a " + shape + " has no dimension \"" + std::string(key) + "\"");
    }
  }
  for (const std::string_view key : dimensions) {
    const double value = positive_length(object, key, std::string(key) + " of the " + shape);
    if (key == "width")
      section.width = value;
    if (key == "depth")
      section.depth = value;
    if (key == "diameter")
      section.diameter = value;
    if (key == "thickness")
      section.thickness = value;
    if (key == "wall")
      section.wall = value;
  }
  std::tie(section.fibers_a, section.fibers_b) = default_fibers;
  if (const auto fibers = object.find("fibers")) {
    if (fibers->expect_array(2, "two fiber counts") != 2) {
      throw fibers->error("expected two fiber counts [a, b] (rectangle: along y and z; circle "
                          "and circular tube: rings and sectors; cruciform and rectangular tube: "
                          "along and through the plates)");
    }
    section.fibers_a = positive_count(fibers->element(0), "fiber count");
    section.fibers_b = positive_count(fibers->element(1), "fiber count");
  }
  try {
    const auto layout = section.mesh(); // the meshers check the geometry (e.g. wall < radius)
    (void)layout;
  } catch (const ParameterError& error) {
    // The meshers name fiber counts by meaning; the file has them as "fibers": [a, b].
    const std::string& field = error.field();
    std::string path = json_pointer_append(object.path(), field);
    if (field == "fibers_y" || field == "rings" || field == "fibers_along") {
      path = json_pointer_append(json_pointer_append(object.path(), "fibers"), "0");
    } else if (field == "fibers_z" || field == "sectors" || field == "fibers_through") {
      path = json_pointer_append(json_pointer_append(object.path(), "fibers"), "1");
    }
    throw InputError(object.source(), path, field + " " + error.what());
  }
  return section;
}

model::ZoneSpec read_zone(const JsonValue& object, std::string_view what) {
  object.expect_object({"length", "section", "elements"}, what);
  model::ZoneSpec zone;
  zone.length = positive_length(object, "length", "zone length at each end");
  zone.section = read_section(object.at("section", "the zone's section"));
  if (const auto elements = object.find("elements")) {
    zone.elements = positive_count(*elements, "number of elements per end");
  }
  return zone;
}

/// Mortar parameters of the brace schema: E, nu, fc, ft, Gf (lc comes from the element).
material::MortarParameters read_mortar_object(const JsonValue& object) {
  object.expect_object({"E", "nu", "fc", "ft", "Gf"},
                       "an object of mortar parameters {E, nu, fc, ft, Gf} (lc comes from the "
                       "element)");
  return read_mortar_fields(object);
}

/// A clearance per side (mm): a finite number >= 0.
double read_gap(const JsonValue& value) {
  const double gap = value.number("clearance per side between core and mortar, mm");
  if (!(gap >= 0.0)) {
    throw value.error("the gap must be >= 0 mm (got " + describe_json_value(value.json()) + ")");
  }
  return gap;
}

/// "gap": one number for both directions or {"y": mm, "z": mm}.
std::pair<double, double> read_gaps(const JsonValue& value) {
  if (!value.json().is_object()) {
    const double both = read_gap(value);
    return {both, both};
  }
  value.expect_object({"y", "z"}, "a gap object {\"y\": mm, \"z\": mm} or a number");
  return {read_gap(value.at("y", "clearance per side along y, mm")),
          read_gap(value.at("z", "clearance per side along z, mm"))};
}

/// Inside size of a casing tube along y and z (mm).
std::pair<double, double> tube_inside(const SectionSpec& tube) {
  if (tube.shape == SectionShape::circular_tube) {
    const double inside = tube.diameter - 2.0 * tube.wall;
    return {inside, inside};
  }
  return {tube.width - 2.0 * tube.wall, tube.depth - 2.0 * tube.wall};
}

std::string millimetres(double value) {
  std::ostringstream text;
  text << value << " mm";
  return text.str();
}

/// Where a section and its gaps leave no room for mortar inside the casing's tube: the first
/// axis along which the tube's inside does not exceed the section's extent + 2 gaps.
struct TubeMisfit {
  const char* axis;
  double inside; ///< the tube's inside (mm)
  double needed; ///< the section's extent + 2 gaps (mm)
};
std::optional<TubeMisfit> misfit_in_tube(const model::CasingSpec& casing,
                                         const SectionSpec& section) {
  const auto [inside_y, inside_z] = tube_inside(casing.tube);
  const auto [extent_y, extent_z] = model::core_extent(section);
  for (const TubeMisfit& candidate : {TubeMisfit{"y", inside_y, extent_y + 2.0 * casing.gap_y},
                                      TubeMisfit{"z", inside_z, extent_z + 2.0 * casing.gap_z}}) {
    if (!(candidate.inside > candidate.needed))
      return candidate;
  }
  return std::nullopt;
}

model::CasingSpec read_casing(const JsonValue& object, const SectionSpec& core,
                              const std::optional<model::ZoneSpec>& transition) {
  object.expect_object({"tube", "outline", "tube_steel", "mortar", "gap", "friction",
                        "layer_stiffness", "fill_fibers", "stopper", "overlap", "core_expansion",
                        "high_mode_waves", "splitting"},
                       "a casing object {tube or outline, tube_steel, mortar, gap, friction, "
                       "layer_stiffness, fill_fibers, stopper, overlap, core_expansion, "
                       "high_mode_waves, splitting} or null");
  model::CasingSpec casing;
  const auto outline = object.find("outline");
  if (outline && object.find("tube")) {
    throw outline->error("give either a steel \"tube\" (filled with mortar) or the \"outline\" "
                         "of a mortar-only casing, not both");
  }
  // A mortar-only casing (no steel tube): its outline, a rectangle or a circle, becomes a
  // tube of wall 0 whose inside the mortar fills.
  const JsonValue tube =
      outline ? *outline
              : object.at("tube", "the casing's steel tube (a rectangular_tube or circular_tube "
                                  "section), or \"outline\" for a mortar-only casing");
  casing.tube = read_section(tube);
  const JsonValue tube_shape = tube.at("shape", "section shape");
  if (outline) {
    casing.steel_tube = false;
    if (casing.tube.shape == SectionShape::rectangle) {
      casing.tube.shape = SectionShape::rectangular_tube;
    } else if (casing.tube.shape == SectionShape::circle) {
      casing.tube.shape = SectionShape::circular_tube;
    } else {
      throw tube_shape.error("the outline of a mortar-only casing must be a rectangle or a "
                             "circle (got " +
                             describe_json_value(tube_shape.json()) + ")");
    }
    casing.tube.wall = 0.0;
    if (const auto steel = object.find("tube_steel")) {
      throw steel->error("a mortar-only casing (\"outline\") has no tube steel");
    }
  } else if (casing.tube.shape != SectionShape::rectangular_tube &&
             casing.tube.shape != SectionShape::circular_tube) {
    throw tube_shape.error("the casing tube must be a rectangular_tube or circular_tube (got " +
                           describe_json_value(tube_shape.json()) + ")");
  }
  if (casing.tube.shape == SectionShape::circular_tube && core.shape != SectionShape::circle) {
    throw tube_shape.error("a circular casing needs a circle core; use a rectangular one "
                           "around this core");
  }
  if (casing.steel_tube) {
    casing.tube_steel = read_steel_object(
        object.at("tube_steel", "the tube steel's parameters (steel schema without lc)"), nullptr);
  }
  casing.mortar =
      read_mortar_object(object.at("mortar", "the mortar fill's parameters {E, nu, fc, ft, Gf}"));

  const JsonValue gap = object.at("gap", "clearance per side between core and mortar, mm: a "
                                         "number or {\"y\": mm, \"z\": mm}");
  std::tie(casing.gap_y, casing.gap_z) = read_gaps(gap);
  if (casing.tube.shape == SectionShape::circular_tube && casing.gap_y != casing.gap_z) {
    throw gap.error("a circular_tube casing has one gap all around: give y and z equal");
  }
  if (const auto friction = object.find("friction")) {
    casing.friction_coefficient = friction->number("Coulomb friction coefficient kappa, -");
    if (!(casing.friction_coefficient >= 0.0)) {
      throw friction->error("the friction coefficient must be >= 0 (got " +
                            describe_json_value(friction->json()) + ")");
    }
  }
  if (const auto expansion = object.find("core_expansion")) {
    casing.core_expansion =
        expansion->number("the core's lateral over axial strain nu_c in the contact, -");
    if (!(casing.core_expansion >= 0.0 && casing.core_expansion <= 0.5)) {
      throw expansion->error("the core expansion nu_c must be in [0, 0.5] (0: off, 0.5: plastic "
                             "incompressibility; got " +
                             describe_json_value(expansion->json()) + ")");
    }
  }
  if (const auto splitting = object.find("splitting")) {
    if (!splitting->json().is_boolean()) {
      throw splitting->error("splitting must be true or false (got " +
                             describe_json_value(splitting->json()) + ")");
    }
    casing.splitting = splitting->json().get<bool>();
    if (casing.splitting && casing.steel_tube) {
      throw splitting->error("splitting is a mortar-only casing's (\"outline\"); a steel tube "
                             "holds the split: remove the key or set it false");
    }
  }
  if (const auto waves = object.find("high_mode_waves")) {
    // true / false, or {"crest_factor": c} (c optional)
    double crest_factor = model::CasingSpec::kDefaultCrestFactor;
    if (waves->json().is_boolean()) {
      if (waves->json().get<bool>())
        casing.high_mode_waves = crest_factor;
    } else {
      waves->expect_object({"crest_factor"},
                           "the sub-element high-mode waves: {\"crest_factor\": c} (default 4), "
                           "true or false");
      if (const auto factor = waves->find("crest_factor")) {
        crest_factor =
            factor->number("crest factor c of the sub-element waves (crest force 4 P g / l at 4)");
        if (!(crest_factor > 0.0 && std::isfinite(crest_factor))) {
          throw factor->error("the crest factor must be > 0 (got " +
                              describe_json_value(factor->json()) + ")");
        }
      }
      casing.high_mode_waves = crest_factor;
    }
  }
  if (const auto layer = object.find("layer_stiffness")) {
    const double stiffness = layer->number("unbonding-layer stiffness, N/mm per mm");
    if (!(stiffness > 0.0)) {
      throw layer->error("the layer stiffness must be > 0 N/mm per mm of core (got " +
                         describe_json_value(layer->json()) + ")");
    }
    casing.layer_stiffness = stiffness;
  }
  if (const auto fibers = object.find("fill_fibers")) {
    if (fibers->expect_array(2, "two fiber counts") != 2) {
      throw fibers->error("expected two fiber counts [a, b] of the mortar fill (through its "
                          "thickness and around it)");
    }
    casing.fill_fibers_a = positive_count(fibers->element(0), "fiber count");
    casing.fill_fibers_b = positive_count(fibers->element(1), "fiber count");
  }
  if (const auto overlap = object.find("overlap")) {
    casing.overlap = overlap->number("length of each transition zone inside the casing, mm");
    if (!transition && casing.overlap != 0.0) {
      throw overlap->error("a casing overlap needs a \"transition\" zone to overlap (the brace "
                           "has none)");
    }
    const double transition_length = transition ? transition->length : 0.0;
    if (!(casing.overlap >= 0.0 && casing.overlap <= transition_length)) {
      throw overlap->error("the casing overlap must be >= 0 and at most the transition length " +
                           millimetres(transition_length) + " (got " +
                           describe_json_value(overlap->json()) + ")");
    }
  }
  if (const auto stopper = object.find("stopper")) {
    stopper->expect_object({"position"}, "a stopper object {\"position\": fraction}");
    if (const auto position = stopper->find("position")) {
      casing.stopper_position =
          position->number("stopper position, fraction of the casing length from its start");
      if (!(casing.stopper_position >= 0.0 && casing.stopper_position <= 1.0)) {
        throw position->error("stopper outside the casing: the position is a fraction of the "
                              "casing's length from its start, in [0, 1] (got " +
                              describe_json_value(position->json()) + ")");
      }
    }
  }

  // The core and its gaps must fit inside the tube, leaving room for mortar; so must the
  // transition's part inside the casing, which keeps the same clearances around its section.
  if (const auto misfit = misfit_in_tube(casing, core)) {
    throw tube.error(std::string("casing too thin for the core: along ") + misfit->axis +
                     " the tube's inside, " + millimetres(misfit->inside) +
                     ", must exceed the core's extent + 2 gaps, " + millimetres(misfit->needed) +
                     ", to leave room for mortar (short by " +
                     millimetres(misfit->needed - misfit->inside) + ")");
  }
  if (casing.overlap > 0.0) {
    if (const auto misfit = misfit_in_tube(casing, transition->section)) {
      throw object.at("overlap", "")
          .error(std::string("the transition section does not fit inside the casing: along ") +
                 misfit->axis + " the tube's inside, " + millimetres(misfit->inside) +
                 ", must exceed the transition's extent + 2 gaps, " + millimetres(misfit->needed) +
                 " (a casing overlap puts the transition inside the casing)");
    }
  }
  // mortar_thickness throws when there is no room; the check above keeps that from happening,
  // up to rounding
  std::pair<double, double> thickness{0.0, 0.0};
  try {
    thickness = casing.mortar_thickness(core);
  } catch (const ParameterError&) {
    // reported below
  }
  if (!(thickness.first > 0.0 && thickness.second > 0.0)) {
    throw tube.error("casing too thin for the core: no mortar between the core's gaps and the "
                     "tube");
  }
  try {
    const auto layout = casing.fill_mesh(core); // checks the fiber counts (e.g. sectors >= 3)
    (void)layout;
  } catch (const ParameterError& error) {
    const std::string& field = error.field();
    std::string path = json_pointer_append(object.path(), "fill_fibers");
    if (field == "rings") {
      path = json_pointer_append(path, "0");
    } else if (field == "sectors") {
      path = json_pointer_append(path, "1");
    }
    throw InputError(object.source(), path, "mortar fill: " + field + " " + error.what());
  }
  return casing;
}

/// The "element" block: how the brace enters a model (fidelity and mode).
model::ElementSpec read_element(const JsonValue& object) {
  object.expect_object({"fidelity", "mode"}, "an element object {fidelity, mode}");
  model::ElementSpec element;
  if (const auto fidelity = object.find("fidelity")) {
    if (fidelity->json().is_string() && fidelity->json().get<std::string>() == "auto") {
      throw fidelity->error("fidelity \"auto\" is not available yet (its rule is still to be "
                            "derived); choose \"full\" or \"truss\"");
    }
    element.fidelity = one_of<model::Fidelity>(
        *fidelity, "element fidelity",
        {{"full", model::Fidelity::full}, {"truss", model::Fidelity::truss}});
  }
  if (const auto mode = object.find("mode")) {
    element.mode = one_of<model::ElementMode>(
        *mode, "element mode",
        {{"condensed", model::ElementMode::condensed}, {"expanded", model::ElementMode::expanded}});
  }
  return element;
}

/// The "solid" block: the 3D continuum mesh (solid/brace_mesh.hpp).
model::SolidMeshSpec read_solid(const JsonValue& object) {
  object.expect_object({"elements_across_core", "axial_element_size", "elements_through_mortar",
                        "half_length", "tube", "end_faces", "steel_density", "mortar_density",
                        "mass_scaling", "threads", "hourglass", "hourglass_min_scale"},
                       "a solid object {elements_across_core, axial_element_size, "
                       "elements_through_mortar, half_length, tube, end_faces, steel_density, "
                       "mortar_density, mass_scaling, threads, hourglass, hourglass_min_scale}");
  model::SolidMeshSpec solid;
  const auto count = [&](std::string_view key, std::string_view meaning, int& value) {
    if (const auto found = object.find(key))
      value = positive_count(*found, meaning);
  };
  count("elements_across_core", "number of elements across the core's smaller side",
        solid.elements_across_core);
  count("elements_through_mortar", "number of elements through the mortar's thickness",
        solid.elements_through_mortar);
  count("threads", "number of threads", solid.threads);
  if (const auto size = object.find("axial_element_size"))
    solid.axial_element_size =
        positive_length(object, "axial_element_size", "target element length along the brace axis");
  if (const auto half = object.find("half_length")) {
    if (!half->json().is_boolean())
      throw half->error("half_length must be true or false (got " +
                        describe_json_value(half->json()) + ")");
    solid.half_length = half->json().get<bool>();
  }
  if (const auto tube = object.find("tube")) {
    solid.tube = one_of<model::SolidTube>(
        *tube, "tube model",
        {{"elements", model::SolidTube::elements}, {"homogenised", model::SolidTube::homogenised}});
  }
  if (const auto ends = object.find("end_faces")) {
    solid.end_faces =
        one_of<model::SolidEndFaces>(*ends, "end faces' support", model::kSolidEndFacesNames);
  }
  for (const auto& [key, value] : {std::pair{"steel_density", &solid.steel_density},
                                   std::pair{"mortar_density", &solid.mortar_density}}) {
    if (const auto found = object.find(key)) {
      *value = found->number("density, tonne/mm^3");
      if (!(*value > 0.0))
        throw found->error("the density must be > 0 tonne/mm^3 (steel 7.85e-9, mortar 2.35e-9; "
                           "got " +
                           describe_json_value(found->json()) + ")");
    }
  }
  if (const auto hourglass = object.find("hourglass")) {
    solid.hourglass =
        one_of<model::SolidHourglass>(*hourglass, "hourglass control", model::kSolidHourglassNames);
  }
  if (const auto floor = object.find("hourglass_min_scale")) {
    solid.hourglass_min_scale = floor->number("floor of the tangent hourglass stiffness scale");
    if (!(solid.hourglass_min_scale > 0.0 && solid.hourglass_min_scale <= 1.0))
      throw floor->error("the hourglass stiffness floor must be in (0, 1] (default 0.05; got " +
                         describe_json_value(floor->json()) + ")");
  }
  if (const auto scaling = object.find("mass_scaling")) {
    solid.mass_scaling = scaling->number("mass scaling factor on the densities");
    if (!(solid.mass_scaling >= 1.0))
      throw scaling->error("the mass scaling factor must be >= 1 (got " +
                           describe_json_value(scaling->json()) + ")");
  }
  return solid;
}

} // namespace

model::BraceSpec parse_brace(std::string_view json_text, const std::string& source) {
  const nlohmann::json document = parse_json(json_text, source);
  const JsonValue root(document, source);
  root.expect_object({"name", "units", "core", "transition", "connection", "ends", "imperfection",
                      "casing", "element", "solid"},
                     "a brace object");
  model::BraceSpec spec;
  if (const auto name = root.find("name"))
    spec.name = name->string("brace name");
  if (const auto units = root.find("units")) {
    const std::string value = units->string("unit system");
    if (value != "mm") {
      throw units->error("unsupported unit system \"" + value + "\"; expected \"mm\" (N, mm, MPa)");
    }
  }

  const JsonValue core = root.at("core", "the steel core {section, steel, yielding_length, ...}");
  core.expect_object({"section", "steel", "yielding_length", "elements", "integration"},
                     "a core object");
  spec.core_section = read_section(core.at("section", "the core's cross-section"));
  spec.steel = read_steel_object(core.at("steel", "the core steel's parameters"), nullptr);
  spec.yielding_length = positive_length(core, "yielding_length", "yielding length of the core");
  if (const auto elements = core.find("elements")) {
    spec.core_elements = positive_count(*elements, "number of core elements");
  }
  if (const auto integration = core.find("integration")) {
    integration->expect_object({"rule", "points"}, "an integration object {rule, points}");
    if (const auto rule = integration->find("rule")) {
      spec.integration_rule = one_of<element::IntegrationRule>(
          *rule, "integration rule",
          {{"gauss_lobatto", element::IntegrationRule::gauss_lobatto},
           {"gauss_legendre", element::IntegrationRule::gauss_legendre}});
    }
    if (const auto points = integration->find("points")) {
      spec.integration_points = positive_count(*points, "number of integration points");
    }
    try {
      element::BeamIntegration::make(spec.integration_rule, spec.integration_points);
    } catch (const ParameterError& error) {
      throw InputError(source, json_pointer_append(integration->path(), "points"), error.what());
    }
  }

  for (const auto& [key, zone] :
       {std::pair{"transition", &spec.transition}, std::pair{"connection", &spec.connection}}) {
    if (const auto value = root.find(key); value && !value->json().is_null()) {
      *zone = read_zone(*value, std::string("a ") + key + " zone {length, section, elements}");
    }
  }

  if (const auto ends = root.find("ends")) {
    spec.ends = one_of<model::EndCondition>(
        *ends, "end conditions",
        {{"pinned", model::EndCondition::pinned}, {"fixed", model::EndCondition::fixed}});
  }

  // Default imperfection: a bow of L/1000 about the weak axis.
  const section::FiberLayout core_layout = spec.core_section.mesh();
  const model::BendingAxis weak = core_layout.second_moment_y() <= core_layout.second_moment_z()
                                      ? model::BendingAxis::z
                                      : model::BendingAxis::y;
  spec.imperfection = {model::ImperfectionShape::bow, spec.total_length() / 1000.0, weak};
  if (const auto imperfection = root.find("imperfection")) {
    imperfection->expect_object({"shape", "amplitude", "direction"},
                                "an imperfection object {shape, amplitude, direction}");
    if (const auto shape = imperfection->find("shape")) {
      spec.imperfection.shape = one_of<model::ImperfectionShape>(
          *shape, "imperfection shape",
          {{"bow", model::ImperfectionShape::bow},
           {"buckling_mode", model::ImperfectionShape::buckling_mode}});
    }
    if (const auto amplitude = imperfection->find("amplitude")) {
      const double value = amplitude->number("imperfection amplitude, mm");
      if (!(value >= 0.0) || value >= spec.total_length()) {
        throw amplitude->error("imperfection amplitude must be >= 0 and smaller than the brace "
                               "length " +
                               std::to_string(spec.total_length()) + " mm (got " +
                               describe_json_value(amplitude->json()) + ")");
      }
      spec.imperfection.amplitude = value;
    }
    if (const auto direction = imperfection->find("direction")) {
      spec.imperfection.direction = one_of<model::BendingAxis>(
          *direction, "imperfection direction",
          {{"y", model::BendingAxis::y}, {"z", model::BendingAxis::z}, {"weak", weak}});
    }
  }

  if (const auto casing = root.find("casing"); casing && !casing->json().is_null()) {
    spec.casing = read_casing(*casing, spec.core_section, spec.transition);
  }
  if (const auto element = root.find("element")) {
    spec.element = read_element(*element);
  }
  if (const auto solid = root.find("solid"); solid && !solid->json().is_null()) {
    spec.solid = read_solid(*solid);
    // the mesh itself: too coarse, a gap or a bow that leaves no mortar, elongated elements
    try {
      solid::validate_brace_mesh(spec, *spec.solid);
    } catch (const ParameterError& error) {
      std::string path;
      std::string_view field = error.field();
      while (!field.empty()) {
        const std::size_t slash = field.find('/');
        path = json_pointer_append(path, field.substr(0, slash));
        field = slash == std::string_view::npos ? std::string_view{} : field.substr(slash + 1);
      }
      throw InputError(source, path, std::string("solid mesh: ") + error.what());
    } catch (const std::invalid_argument& error) {
      throw InputError(source, solid->path(), std::string("solid mesh: ") + error.what());
    }
  }
  return spec;
}

model::BraceSpec read_brace(const std::filesystem::path& file) {
  return parse_brace(read_text_file(file), file.string());
}

material::MortarParameters read_mortar_fields(const JsonValue& object) {
  const auto required = [&object](std::string_view key, std::string_view meaning) {
    return object.at(key, meaning).number(meaning);
  };
  material::MortarParameters mortar;
  mortar.youngs_modulus = required("E", "Young's modulus E, MPa");
  mortar.poissons_ratio = required("nu", "Poisson's ratio nu");
  mortar.compressive_strength = required("fc", "compressive strength fc, MPa");
  mortar.tensile_strength = required("ft", "tensile strength ft, MPa");
  mortar.fracture_energy = required("Gf", "fracture energy Gf, N/mm");
  try {
    mortar.validate();
  } catch (const ParameterError& error) {
    throw InputError(object.source(), object.path() + json_path_of_parameter(error.field()),
                     error.what());
  }
  return mortar;
}

} // namespace brb::io
