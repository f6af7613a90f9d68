#include "brb/io/frame_input.hpp"

#include "brb/io/brace_input.hpp"
#include "brb/io/json_input.hpp"
#include "brb/io/material_input.hpp"
#include "brb/material/parameter_error.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace brb::io {
namespace {

using element::Vector3;
using model::Dof;
using nlohmann::json;

constexpr std::array<std::string_view, model::kDofPerNode> kDofNames{"ux", "uy", "uz",
                                                                     "rx", "ry", "rz"};

/// A planar model's nodes lie in the X-Z plane: |y| above this (mm) is an error.
constexpr double kPlanarTolerance = 1e-6;

/// An orientation vector whose angle with the member is below this (rad, as a sine) is
/// taken as parallel: it defines no local x-z plane.
constexpr double kParallelSine = 1e-6;

std::string format_number(double value) {
  std::ostringstream text;
  text << std::setprecision(10) << value;
  return text.str();
}

std::string millimetres(double value) {
  return format_number(value) + " mm";
}

bool boolean(const JsonValue& value, std::string_view meaning) {
  if (!value.json().is_boolean()) {
    throw value.error("expected true or false (" + std::string(meaning) + "), got " +
                      describe_json_value(value.json()));
  }
  return value.json().get<bool>();
}

/// A whole number in [minimum, maximum].
int whole_number(const JsonValue& value, std::string_view meaning, int minimum,
                 int maximum = INT_MAX) {
  const double number = value.number(meaning);
  if (number != std::floor(number) || number < minimum || number > maximum) {
    const std::string range = maximum == INT_MAX ? ">= " + std::to_string(minimum)
                                                 : "in [" + std::to_string(minimum) + ", " +
                                                       std::to_string(maximum) + "]";
    throw value.error(std::string(meaning) + " must be a whole number " + range + " (got " +
                      describe_json_value(value.json()) + ")");
  }
  return static_cast<int>(number);
}

int positive_id(const JsonValue& value, std::string_view meaning) {
  return whole_number(value, meaning, 1);
}

double positive(const JsonValue& value, std::string_view meaning, std::string_view unit) {
  const double number = value.number(meaning);
  if (!(number > 0.0)) {
    throw value.error(std::string(meaning) + " must be > 0" + std::string(unit) + " (got " +
                      describe_json_value(value.json()) + ")");
  }
  return number;
}

double non_negative(const JsonValue& value, std::string_view meaning, std::string_view unit) {
  const double number = value.number(meaning);
  if (!(number >= 0.0)) {
    throw value.error(std::string(meaning) + " must be >= 0" + std::string(unit) + " (got " +
                      describe_json_value(value.json()) + ")");
  }
  return number;
}

/// A damping ratio: in [0, 1).
double damping_ratio(const JsonValue& value) {
  const double ratio = value.number("damping ratio, -");
  if (!(ratio >= 0.0 && ratio < 1.0)) {
    throw value.error("a damping ratio must be in [0, 1) (got " +
                      describe_json_value(value.json()) + ")");
  }
  return ratio;
}

/// A string option: the value paired with the text found, or an error listing the choices.
template <class Value>
Value one_of(const JsonValue& option, std::string_view meaning,
             std::initializer_list<std::pair<std::string_view, Value>> choices) {
  const std::string text = option.string(meaning);
  std::string names;
  for (const auto& [name, value] : choices) {
    if (text == name)
      return value;
    names += (names.empty() ? "" : ", ") + ("\"" + std::string(name) + "\"");
  }
  throw option.error("unknown " + std::string(meaning) + " \"" + text + "\"; expected one of " +
                     names);
}

/// An array of exactly `size` elements.
void expect_size(const JsonValue& value, std::size_t size, std::string_view what) {
  if (value.expect_array(size, what) != size) {
    throw value.error("expected " + std::to_string(size) + " elements (" + std::string(what) +
                      "), got " + std::to_string(value.json().size()));
  }
}

Vector3 read_vector3(const JsonValue& value, std::string_view what) {
  expect_size(value, 3, what);
  return {value.element(0).number(what), value.element(1).number(what),
          value.element(2).number(what)};
}

Dof read_dof_name(const JsonValue& value) {
  const std::string name = value.string("a DOF name: ux, uy, uz, rx, ry or rz");
  for (std::size_t index = 0; index < kDofNames.size(); ++index) {
    if (name == kDofNames[index])
      return static_cast<Dof>(index);
  }
  throw value.error("unknown DOF \"" + name + "\"; expected one of ux, uy, uz, rx, ry, rz");
}

/// A non-empty list of distinct DOF names.
std::vector<Dof> read_dof_list(const JsonValue& value) {
  const std::size_t count = value.expect_array(model::kDofPerNode, "DOF names");
  if (count == 0)
    throw value.error("expected at least one DOF name (ux, uy, uz, rx, ry, rz)");
  std::vector<Dof> dofs;
  for (std::size_t index = 0; index < count; ++index) {
    const JsonValue entry = value.element(index);
    const Dof dof = read_dof_name(entry);
    if (std::find(dofs.begin(), dofs.end(), dof) != dofs.end())
      throw entry.error("DOF \"" + std::string(kDofNames[dof]) + "\" is listed twice");
    dofs.push_back(dof);
  }
  return dofs;
}

/// Parses the JSON `document` with `parse` (a reader of another schema taking text and a
/// source) as if it stood in the frame file, so that its errors name the frame file: each
/// error location starting with a prefix of `locations` is moved to the matching frame
/// path; any other location (including the top level) goes to `fallback`.
template <class Parse>
auto parse_embedded(const json& document, const std::string& source,
                    const std::vector<std::pair<std::string, std::string>>& locations,
                    const std::string& fallback, Parse&& parse) {
  try {
    return parse(document.dump(), source);
  } catch (const InputError& error) {
    const std::string& location = error.location();
    for (const auto& [prefix, frame_path] : locations) {
      if (location.starts_with(prefix) &&
          (location.size() == prefix.size() || location[prefix.size()] == '/')) {
        throw InputError(source, frame_path + location.substr(prefix.size()), error.expected());
      }
    }
    throw InputError(source, fallback, error.expected());
  }
}

/// Mortar parameters of a frame material: E, nu, fc, ft, Gf (lc comes from the element).
material::MortarParameters read_mortar_law(const JsonValue& object) {
  object.expect_object({"law", "units", "E", "nu", "fc", "ft", "Gf"},
                       "mortar parameters {law, E, nu, fc, ft, Gf}");
  if (const auto units = object.find("units")) {
    const std::string value = units->string("unit system");
    if (value != "MPa")
      throw units->error("unsupported unit system \"" + value + "\"; expected \"MPa\"");
  }
  return read_mortar_fields(object);
}

/// Node ids and where each was defined, to resolve references.
class NodeTable {
public:
  explicit NodeTable(const std::vector<model::FrameNodeSpec>& nodes) {
    for (std::size_t index = 0; index < nodes.size(); ++index)
      index_[nodes[index].id] = index;
  }

  /// The node id at `value`, which must be defined; `who` names the referring item in the
  /// message (e.g. "element 5").
  int reference(const JsonValue& value, const std::string& who) const {
    const int id = positive_id(value, "node id");
    if (!index_.contains(id)) {
      throw value.error(who + " refers to node " + std::to_string(id) +
                        ", which does not exist: expected the id of a node of /nodes");
    }
    return id;
  }

private:
  std::map<int, std::size_t> index_;
};

class FrameReader {
public:
  FrameReader(const JsonValue& root, std::filesystem::path base_directory)
      : root_(root), source_(root.source()), base_directory_(std::move(base_directory)) {}

  model::FrameSpec read() {
    root_.expect_object({"title", "units", "dimension", "nodes", "supports", "constraints",
                         "masses", "sections", "materials", "elements", "gravity", "damping",
                         "analysis", "ground_motion", "stories", "floors", "recorders", "design"},
                        "a frame model object");
    // "design" documents how the frame was designed; nothing in the analysis reads it.
    if (const auto title = root_.find("title"))
      spec_.title = title->string("title of the model");
    if (const auto units = root_.find("units"))
      read_units(*units);
    spec_.dimension = static_cast<model::FrameDimension>(
        whole_number(root_.at("dimension", "2 (planar, in the X-Z plane) or 3"),
                     "dimension: 2 (planar, in the X-Z plane) or 3 (spatial)", 2, 3));
    read_nodes(root_.at("nodes", "the nodes [{\"id\", \"xyz\"}, ...]"));
    const NodeTable nodes(spec_.nodes);
    if (const auto supports = root_.find("supports"))
      read_supports(*supports, nodes);
    if (const auto constraints = root_.find("constraints"))
      read_constraints(*constraints, nodes);
    if (const auto masses = root_.find("masses"))
      read_masses(*masses, nodes);
    if (const auto sections = root_.find("sections"))
      read_sections(*sections);
    if (const auto materials = root_.find("materials"))
      read_materials(*materials);
    read_elements(root_.at("elements", "the elements [{\"id\", \"type\", \"nodes\", ...}]"), nodes);
    if (const auto gravity = root_.find("gravity"))
      read_gravity(*gravity, nodes);
    if (const auto damping = root_.find("damping"))
      read_damping(*damping);
    if (const auto analysis = root_.find("analysis"))
      read_analysis(*analysis);
    if (const auto ground_motion = root_.find("ground_motion"))
      read_ground_motion(*ground_motion);
    if (const auto stories = root_.find("stories"))
      read_stories(*stories, nodes);
    if (const auto floors = root_.find("floors"))
      read_floors(*floors, nodes);
    if (const auto recorders = root_.find("recorders"))
      read_recorders(*recorders);
    check_mass();
    return std::move(spec_);
  }

private:
  void read_units(const JsonValue& units) {
    units.expect_object({"length", "force", "mass"},
                        "a units object {\"length\": \"mm\", \"force\": \"N\", \"mass\": "
                        "\"tonne\"}");
    for (const auto& [key, supported] :
         {std::pair{"length", "mm"}, std::pair{"force", "N"}, std::pair{"mass", "tonne"}}) {
      if (const auto unit = units.find(key)) {
        const std::string value = unit->string(std::string(key) + " unit");
        if (value != supported) {
          throw unit->error("unsupported " + std::string(key) + " unit \"" + value + "\"; only \"" +
                            supported + "\" is supported for now (units: mm, N, tonne, s, MPa)");
        }
      }
    }
  }

  void read_nodes(const JsonValue& nodes) {
    const std::size_t count = nodes.expect_array(SIZE_MAX, "nodes {\"id\", \"xyz\"}");
    if (count == 0)
      throw nodes.error("expected at least one node");
    std::map<int, std::string> defined;
    for (std::size_t index = 0; index < count; ++index) {
      const JsonValue node = nodes.element(index);
      node.expect_object({"id", "xyz"}, "a node {\"id\": positive integer, \"xyz\": [x, y, z]}");
      const JsonValue id_value = node.at("id", "node id, a positive integer");
      const int id = positive_id(id_value, "node id");
      if (const auto [first, inserted] = defined.emplace(id, node.path()); !inserted) {
        throw id_value.error("duplicate node id " + std::to_string(id) + ": already defined at " +
                             first->second + "; node ids must be unique");
      }
      const JsonValue xyz = node.at("xyz", "coordinates [x, y, z], mm");
      const Vector3 coordinates = read_vector3(xyz, "coordinates [x, y, z], mm");
      if (spec_.dimension == model::FrameDimension::planar &&
          std::abs(coordinates.y()) > kPlanarTolerance) {
        throw xyz.element(1).error("a planar model (dimension 2) lies in the X-Z plane: y must "
                                   "be 0 mm (got " +
                                   describe_json_value(xyz.element(1).json()) + ")");
      }
      spec_.nodes.push_back({id, coordinates});
    }
  }

  void read_supports(const JsonValue& supports, const NodeTable& nodes) {
    const std::size_t count = supports.expect_array(SIZE_MAX, "supports {\"node\", \"fix\"}");
    for (std::size_t index = 0; index < count; ++index) {
      const JsonValue support = supports.element(index);
      support.expect_object({"node", "fix"}, "a support {\"node\": id, \"fix\": ...}");
      model::SupportSpec spec;
      spec.node = nodes.reference(support.at("node", "the supported node's id"), "a support");
      const JsonValue fix = support.at(
          "fix", "the fixed DOF: \"fixed\" (all six), \"pinned\" (translations) or a list of "
                 "DOF names");
      if (fix.json().is_string()) {
        const std::string kind = fix.string("fixity");
        if (kind == "fixed") {
          spec.fixed.fill(true);
        } else if (kind == "pinned") {
          spec.fixed = {true, true, true, false, false, false};
        } else {
          throw fix.error("unknown fixity \"" + kind +
                          "\"; expected \"fixed\", \"pinned\" or a list of DOF names "
                          "(ux, uy, uz, rx, ry, rz)");
        }
      } else {
        for (const Dof dof : read_dof_list(fix))
          spec.fixed[dof] = true;
      }
      spec_.supports.push_back(spec);
    }
  }

  void read_constraints(const JsonValue& constraints, const NodeTable& nodes) {
    const std::size_t count =
        constraints.expect_array(SIZE_MAX, "constraints (rigid_diaphragm or equal_dof)");
    for (std::size_t index = 0; index < count; ++index) {
      const JsonValue constraint = constraints.element(index);
      if (!constraint.json().is_object()) {
        throw constraint.error("expected a constraint object {\"type\": \"rigid_diaphragm\" or "
                               "\"equal_dof\", ...}, got " +
                               describe_json_value(constraint.json()));
      }
      const JsonValue type = constraint.at("type", "rigid_diaphragm or equal_dof");
      const std::string kind = type.string("constraint type");
      if (kind == "rigid_diaphragm") {
        constraint.expect_object({"type", "master", "nodes"},
                                 "a rigid diaphragm {type, master, nodes}");
        const std::string who = "a rigid diaphragm";
        model::RigidDiaphragmConstraint diaphragm;
        diaphragm.master = nodes.reference(constraint.at("master", "the master node's id"), who);
        const JsonValue slaves = constraint.at("nodes", "the ids of the nodes that follow the "
                                                        "master in the X-Y plane");
        const std::size_t slave_count = slaves.expect_array(SIZE_MAX, "node ids");
        if (slave_count == 0)
          throw slaves.error("expected at least one node id");
        for (std::size_t slave = 0; slave < slave_count; ++slave) {
          const JsonValue entry = slaves.element(slave);
          const int id = nodes.reference(entry, who);
          if (id == diaphragm.master)
            throw entry.error("the master node " + std::to_string(id) + " cannot be its own slave");
          if (std::find(diaphragm.slaves.begin(), diaphragm.slaves.end(), id) !=
              diaphragm.slaves.end())
            throw entry.error("node " + std::to_string(id) + " is listed twice");
          diaphragm.slaves.push_back(id);
        }
        spec_.rigid_diaphragms.push_back(std::move(diaphragm));
      } else if (kind == "equal_dof") {
        constraint.expect_object({"type", "master", "slave", "dofs"},
                                 "an equal_dof constraint {type, master, slave, dofs}");
        const std::string who = "an equal_dof constraint";
        model::EqualDofConstraint equal;
        equal.master = nodes.reference(constraint.at("master", "the master node's id"), who);
        const JsonValue slave = constraint.at("slave", "the slave node's id");
        equal.slave = nodes.reference(slave, who);
        if (equal.slave == equal.master)
          throw slave.error("the slave must differ from the master node " +
                            std::to_string(equal.master));
        equal.dofs = read_dof_list(constraint.at("dofs", "the DOF names the slave shares"));
        spec_.equal_dofs.push_back(std::move(equal));
      } else {
        throw type.error("unknown constraint type \"" + kind +
                         "\"; expected \"rigid_diaphragm\" or \"equal_dof\"");
      }
    }
  }

  void read_masses(const JsonValue& masses, const NodeTable& nodes) {
    const std::size_t count = masses.expect_array(SIZE_MAX, "nodal masses {\"node\", \"mass\"}");
    for (std::size_t index = 0; index < count; ++index) {
      const JsonValue entry = masses.element(index);
      entry.expect_object({"node", "mass"}, "a nodal mass {\"node\": id, \"mass\": ...}");
      model::NodalMassSpec spec;
      spec.node = nodes.reference(entry.at("node", "the node's id"), "a mass");
      const JsonValue mass = entry.at(
          "mass", "tonne: one number (ux, uy, uz) or six [mx, my, mz, Ixx, Iyy, Izz] (tonne, "
                  "tonne mm^2)");
      if (mass.json().is_array()) {
        expect_size(mass, model::kDofPerNode,
                    "[mx, my, mz, Ixx, Iyy, Izz] in tonne and tonne mm^2");
        for (std::size_t dof = 0; dof < model::kDofPerNode; ++dof) {
          spec.mass[dof] = non_negative(mass.element(dof), "mass", "");
        }
      } else {
        const double translational = non_negative(mass, "mass", " tonne");
        spec.mass = {translational, translational, translational, 0.0, 0.0, 0.0};
      }
      spec_.masses.push_back(spec);
    }
  }

  void read_sections(const JsonValue& sections) {
    if (!sections.json().is_object()) {
      throw sections.error("expected an object of named sections {\"name\": {E, G, A, Iy, Iz, "
                           "J}}, got " +
                           describe_json_value(sections.json()));
    }
    for (const auto& member : sections.json().items()) {
      const JsonValue section = *sections.find(member.key());
      section.expect_object({"E", "G", "A", "Iy", "Iz", "J"},
                            "elastic section properties {E, G, A, Iy, Iz, J} (MPa, mm)");
      const auto required = [&section](std::string_view key, std::string_view meaning,
                                       std::string_view unit) {
        return positive(section.at(key, meaning), meaning, unit);
      };
      spec_.sections[member.key()] = model::ElasticSectionSpec{
          .youngs_modulus = required("E", "Young's modulus E", " MPa"),
          .shear_modulus = required("G", "shear modulus G", " MPa"),
          .area = required("A", "area A", " mm^2"),
          .inertia_y = required("Iy", "second moment Iy (bending about local y)", " mm^4"),
          .inertia_z = required("Iz", "second moment Iz (bending about local z)", " mm^4"),
          .torsion_constant = required("J", "torsion constant J", " mm^4"),
      };
    }
  }

  void read_materials(const JsonValue& materials) {
    if (!materials.json().is_object()) {
      throw materials.error("expected an object of named uniaxial materials {\"name\": "
                            "{\"law\": ..., ...}}, got " +
                            describe_json_value(materials.json()));
    }
    for (const auto& member : materials.json().items()) {
      const JsonValue material = *materials.find(member.key());
      if (!material.json().is_object()) {
        throw material.error("expected a material object {\"law\": \"elastic\", \"steel\" or "
                             "\"mortar\", parameters...}, got " +
                             describe_json_value(material.json()));
      }
      const std::string law = one_of<std::string>(
          material.at("law", "the uniaxial law: elastic, steel or mortar"), "uniaxial law",
          {{"elastic", "elastic"}, {"steel", "steel"}, {"mortar", "mortar"}});
      if (law == "elastic") {
        material.expect_object({"law", "E"}, "an elastic law {\"law\": \"elastic\", \"E\"}");
        spec_.materials[member.key()] = model::ElasticLaw{positive(
            material.at("E", "modulus E (MPa; N/mm or N mm/rad in a spring)"), "modulus E", "")};
      } else if (law == "steel") {
        // The steel schema of `brb material` without lc: a copy without "law" is read by
        // the steel reader at the same JSON path (the keys are checked here first so that an
        // unknown key's message lists "law" too).
        material.expect_object(
            {"law", "units", "E", "nu", "fy", "H_kin", "H_iso", "chaboche", "voce", "fu", "Gf"},
            "steel parameters {law, E, nu, fy, H_kin, H_iso, ...} (lc comes from the element)");
        json parameters = material.json();
        parameters.erase("law");
        const JsonValue steel(parameters, source_, material.path());
        spec_.materials[member.key()] = read_steel_object(steel, nullptr);
      } else {
        spec_.materials[member.key()] = read_mortar_law(material);
      }
    }
  }

  model::NamedLaw material_reference(const JsonValue& value) const {
    const std::string name = value.string("the name of a material of /materials");
    const auto found = spec_.materials.find(name);
    if (found == spec_.materials.end()) {
      throw value.error("unknown material \"" + name +
                        "\"; expected one of /materials: " + names_of(spec_.materials));
    }
    return {name, found->second};
  }

  template <class Map> static std::string names_of(const Map& map) {
    if (map.empty())
      return "(none defined)";
    std::string names;
    for (const auto& [name, value] : map)
      names += (names.empty() ? "" : ", ") + name;
    return names;
  }

  void read_elements(const JsonValue& elements, const NodeTable& nodes) {
    const std::size_t count = elements.expect_array(SIZE_MAX, "elements");
    if (count == 0)
      throw elements.error("expected at least one element");
    std::map<int, std::string> defined;
    for (std::size_t index = 0; index < count; ++index) {
      const JsonValue element = elements.element(index);
      if (!element.json().is_object()) {
        throw element.error("expected an element object {\"id\", \"type\", \"nodes\", ...}, got " +
                            describe_json_value(element.json()));
      }
      model::FrameElementSpec spec;
      const JsonValue id_value = element.at("id", "element id, a positive integer");
      spec.id = positive_id(id_value, "element id");
      if (const auto [first, inserted] = defined.emplace(spec.id, element.path()); !inserted) {
        throw id_value.error("duplicate element id " + std::to_string(spec.id) +
                             ": already defined at " + first->second +
                             "; element ids must be unique");
      }
      const JsonValue type =
          element.at("type", "element type: elastic_beam, truss, spring, fiber_beam or brb");
      const std::string kind = type.string("element type");
      const std::string who = "element " + std::to_string(spec.id);
      if (kind == "elastic_beam") {
        element.expect_object({"id", "type", "nodes", "section", "geometry", "orientation"},
                              "an elastic_beam element");
        read_element_nodes(element, nodes, who, spec, true);
        spec.kind = read_elastic_beam(element, spec);
      } else if (kind == "truss") {
        element.expect_object({"id", "type", "nodes", "area", "material"}, "a truss element");
        read_element_nodes(element, nodes, who, spec, true);
        spec.kind = model::TrussSpec{
            .area = positive(element.at("area", "cross-section area A, mm^2"), "area", " mm^2"),
            .material = material_reference(element.at("material", "the name of its material")),
        };
      } else if (kind == "spring") {
        element.expect_object({"id", "type", "nodes", "dofs"}, "a spring element");
        read_element_nodes(element, nodes, who, spec, false);
        spec.kind = read_spring(element);
      } else if (kind == "fiber_beam") {
        element.expect_object({"id", "type", "nodes", "section", "steel", "subdivisions",
                               "integration", "orientation"},
                              "a fiber_beam element");
        read_element_nodes(element, nodes, who, spec, true);
        spec.kind = read_fiber_beam(element, spec);
      } else if (kind == "brb") {
        element.expect_object({"id", "type", "nodes", "brace", "fidelity", "mode", "orientation"},
                              "a brb element");
        read_element_nodes(element, nodes, who, spec, true);
        spec.kind = read_brace_element(element, spec);
      } else {
        throw type.error("unknown element type \"" + kind +
                         "\"; expected one of elastic_beam, truss, spring, fiber_beam, brb");
      }
      spec_.elements.push_back(std::move(spec));
    }
  }

  /// "nodes": [i, j], two distinct defined nodes; with `needs_length` also apart in space.
  void read_element_nodes(const JsonValue& element, const NodeTable& nodes, const std::string& who,
                          model::FrameElementSpec& spec, bool needs_length) const {
    const JsonValue ends = element.at("nodes", "the ids of its two nodes [i, j]");
    expect_size(ends, 2, "the ids of the element's two nodes [i, j]");
    spec.nodes = {nodes.reference(ends.element(0), who), nodes.reference(ends.element(1), who)};
    if (spec.nodes[0] == spec.nodes[1]) {
      throw ends.error(who + " connects node " + std::to_string(spec.nodes[0]) +
                       " to itself: expected two different nodes");
    }
    if (needs_length && !(spec_.element_length(spec) > 0.0)) {
      throw ends.error(who + " has zero length: nodes " + std::to_string(spec.nodes[0]) + " and " +
                       std::to_string(spec.nodes[1]) +
                       " are at the same place; expected two nodes apart");
    }
  }

  /// "orientation": a vector in the local x-z plane, not parallel to the member.
  std::optional<Vector3> read_orientation(const JsonValue& element,
                                          const model::FrameElementSpec& spec) const {
    const auto value = element.find("orientation");
    if (!value)
      return std::nullopt;
    const Vector3 orientation =
        read_vector3(*value, "orientation: a vector [x, y, z] in the local x-z plane");
    const Vector3 axis =
        spec_.node(spec.nodes[1]).coordinates - spec_.node(spec.nodes[0]).coordinates;
    if (!(orientation.cross(axis).norm() > kParallelSine * orientation.norm() * axis.norm())) {
      throw value->error("the orientation vector must not be zero or parallel to the member "
                         "(it defines the local x-z plane)");
    }
    return orientation;
  }

  model::ElasticBeamSpec read_elastic_beam(const JsonValue& element,
                                           const model::FrameElementSpec& spec) const {
    model::ElasticBeamSpec beam;
    const JsonValue section = element.at("section", "the name of a section of /sections");
    beam.section_name = section.string("the name of a section of /sections");
    const auto found = spec_.sections.find(beam.section_name);
    if (found == spec_.sections.end()) {
      throw section.error("unknown section \"" + beam.section_name +
                          "\"; expected one of /sections: " + names_of(spec_.sections));
    }
    beam.section = found->second;
    if (const auto geometry = element.find("geometry")) {
      beam.geometry =
          one_of<model::BeamGeometry>(*geometry, "geometry",
                                      {{"linear", model::BeamGeometry::linear},
                                       {"pdelta", model::BeamGeometry::pdelta},
                                       {"corotational", model::BeamGeometry::corotational}});
    }
    beam.orientation = read_orientation(element, spec);
    return beam;
  }

  model::SpringSpec read_spring(const JsonValue& element) const {
    const JsonValue dofs = element.at(
        "dofs", "the law of each DOF: {\"ux\": material name, ...} (ux, uy, uz, rx, ry, rz)");
    dofs.expect_object({"ux", "uy", "uz", "rx", "ry", "rz"}, "an object {DOF name: material name}");
    if (dofs.json().empty())
      throw dofs.error("expected at least one DOF with a material (ux, uy, uz, rx, ry, rz)");
    model::SpringSpec spring;
    for (std::size_t dof = 0; dof < kDofNames.size(); ++dof) {
      if (const auto material = dofs.find(kDofNames[dof]))
        spring.dofs[dof] = material_reference(*material);
    }
    return spring;
  }

  /// A fiber beam's section, steel and integration have the schema of a brace core: they are
  /// read by the brace reader, as the core of a bare brace as long as the member, and its
  /// errors are located at the element's keys.
  model::FiberBeamSpec read_fiber_beam(const JsonValue& element,
                                       const model::FrameElementSpec& spec) const {
    const JsonValue section = element.at("section", "a section object (brace-file schema)");
    const JsonValue steel = element.at("steel", "the steel parameters (steel schema without lc)");
    json core = {{"section", section.json()},
                 {"steel", steel.json()},
                 {"yielding_length", spec_.element_length(spec)}};
    std::vector<std::pair<std::string, std::string>> locations{{"/core/section", section.path()},
                                                               {"/core/steel", steel.path()}};
    if (const auto integration = element.find("integration")) {
      core["integration"] = integration->json();
      locations.emplace_back("/core/integration", integration->path());
    }
    const model::BraceSpec brace =
        parse_embedded(json{{"core", std::move(core)}}, source_, locations, element.path(),
                       [](const std::string& text, const std::string& source) {
                         return parse_brace(text, source);
                       });
    model::FiberBeamSpec beam;
    beam.section = brace.core_section;
    beam.steel = brace.steel;
    beam.integration_rule = brace.integration_rule;
    beam.integration_points = brace.integration_points;
    if (const auto subdivisions = element.find("subdivisions"))
      beam.subdivisions = whole_number(*subdivisions, "number of elements along the member", 1);
    beam.orientation = read_orientation(element, spec);
    return beam;
  }

  model::BraceElementSpec read_brace_element(const JsonValue& element,
                                             const model::FrameElementSpec& spec) const {
    model::BraceElementSpec brace;
    const JsonValue value =
        element.at("brace", "a brace file (path relative to the frame file) or a brace object");
    if (value.json().is_string()) {
      const std::string relative = value.string("brace file");
      brace.source_file = base_directory_ / relative;
      try {
        brace.brace = read_brace(brace.source_file);
      } catch (const InputError& error) {
        throw value.error("brace file \"" + relative + "\" is missing or invalid: " + error.what());
      }
    } else if (value.json().is_object()) {
      brace.brace = parse_embedded(value.json(), source_, {{"", value.path()}}, value.path(),
                                   [](const std::string& text, const std::string& source) {
                                     return parse_brace(text, source);
                                   });
    } else {
      throw value.error("expected a brace file name (a string) or a brace object, got " +
                        describe_json_value(value.json()));
    }
    const double distance = spec_.element_length(spec);
    const double length = brace.brace.total_length();
    if (!(std::abs(length - distance) <= kBraceLengthTolerance)) {
      throw value.error(
          "the brace's length, " + millimetres(length) +
          " (yielding length + transition and connection lengths at both ends), differs from "
          "the distance between nodes " +
          std::to_string(spec.nodes[0]) + " and " + std::to_string(spec.nodes[1]) + ", " +
          millimetres(distance) + ", by " + millimetres(std::abs(length - distance)) +
          "; expected them equal within " + millimetres(kBraceLengthTolerance));
    }
    if (const auto fidelity = element.find("fidelity")) {
      brace.fidelity = one_of<model::BraceFidelity>(*fidelity, "brace fidelity",
                                                    {{"auto", model::BraceFidelity::automatic},
                                                     {"full", model::BraceFidelity::full},
                                                     {"truss", model::BraceFidelity::truss}});
    }
    if (const auto mode = element.find("mode")) {
      brace.mode = one_of<model::ElementMode>(*mode, "brace mode",
                                              {{"condensed", model::ElementMode::condensed},
                                               {"expanded", model::ElementMode::expanded}});
    }
    brace.orientation = read_orientation(element, spec);
    return brace;
  }

  void read_gravity(const JsonValue& gravity, const NodeTable& nodes) {
    gravity.expect_object({"from_masses", "loads", "steps"},
                          "a gravity object {from_masses, loads, steps}");
    model::GravitySpec spec;
    if (const auto from_masses = gravity.find("from_masses"))
      spec.from_masses = boolean(*from_masses, "add m g along -Z for every nodal mass");
    if (const auto loads = gravity.find("loads")) {
      const std::size_t count = loads->expect_array(SIZE_MAX, "nodal loads {\"node\", \"force\"}");
      for (std::size_t index = 0; index < count; ++index) {
        const JsonValue load = loads->element(index);
        load.expect_object({"node", "force"},
                           "a nodal load {\"node\": id, \"force\": [Fx, Fy, Fz, Mx, My, Mz]}");
        model::NodalLoadSpec nodal;
        nodal.node = nodes.reference(load.at("node", "the loaded node's id"), "a gravity load");
        const JsonValue force =
            load.at("force", "[Fx, Fy, Fz, Mx, My, Mz] in N and N mm (global axes)");
        expect_size(force, model::kDofPerNode, "[Fx, Fy, Fz, Mx, My, Mz] in N and N mm");
        for (std::size_t dof = 0; dof < model::kDofPerNode; ++dof)
          nodal.force[dof] = force.element(dof).number("force, N or N mm");
        spec.loads.push_back(nodal);
      }
    }
    if (const auto steps = gravity.find("steps"))
      spec.steps = whole_number(*steps, "number of load steps", 1);
    spec_.gravity = std::move(spec);
  }

  void read_damping(const JsonValue& damping) {
    if (!damping.json().is_object()) {
      throw damping.error("expected a damping object {\"type\": \"rayleigh\" or \"modal\", "
                          "...}, got " +
                          describe_json_value(damping.json()));
    }
    const JsonValue type = damping.at("type", "rayleigh or modal");
    const std::string kind =
        one_of<std::string>(type, "damping type", {{"rayleigh", "rayleigh"}, {"modal", "modal"}});
    if (kind == "rayleigh") {
      damping.expect_object({"type", "modes", "ratios", "stiffness", "exclude_braces"},
                            "Rayleigh damping {type, modes, ratios, stiffness, exclude_braces}");
      model::RayleighDampingSpec rayleigh;
      const JsonValue modes = damping.at("modes", "the two mode numbers [i, j]");
      expect_size(modes, 2, "two mode numbers [i, j], 1 = the first mode");
      for (std::size_t index = 0; index < 2; ++index)
        rayleigh.modes[index] = whole_number(modes.element(index), "mode number", 1);
      if (rayleigh.modes[0] == rayleigh.modes[1])
        throw modes.element(1).error("the two modes must differ (got mode " +
                                     std::to_string(rayleigh.modes[0]) + " twice)");
      const JsonValue ratios = damping.at("ratios", "the damping ratios at the two modes");
      expect_size(ratios, 2, "two damping ratios");
      for (std::size_t index = 0; index < 2; ++index)
        rayleigh.ratios[index] = damping_ratio(ratios.element(index));
      if (const auto stiffness = damping.find("stiffness")) {
        one_of<int>(*stiffness,
                    "stiffness of the Rayleigh damping (only the initial stiffness "
                    "is supported)",
                    {{"initial", 0}});
      }
      if (const auto exclude = damping.find("exclude_braces"))
        rayleigh.exclude_braces = boolean(*exclude, "keep the brb elements out of K0");
      spec_.damping = rayleigh;
    } else {
      damping.expect_object({"type", "ratio", "modes"}, "modal damping {type, ratio, modes}");
      spec_.damping = model::ModalDampingSpec{
          .ratio = damping_ratio(damping.at("ratio", "the damping ratio of every mode")),
          .modes =
              whole_number(damping.at("modes", "how many modes are damped"), "number of modes", 1),
      };
    }
  }

  void read_analysis(const JsonValue& analysis) {
    analysis.expect_object({"integrator", "dt", "alpha", "free_vibration", "drift_limit"},
                           "an analysis object {integrator, dt, alpha, free_vibration, "
                           "drift_limit}");
    model::AnalysisSpec& spec = spec_.analysis;
    if (const auto integrator = analysis.find("integrator")) {
      spec.integrator =
          one_of<model::Integrator>(*integrator, "integrator",
                                    {{"newmark", model::Integrator::newmark},
                                     {"hht", model::Integrator::hht},
                                     {"explicit", model::Integrator::explicit_central_difference}});
    }
    if (const auto dt = analysis.find("dt"))
      spec.dt = positive(*dt, "time step dt", " s");
    const auto alpha = analysis.find("alpha");
    if (spec.integrator == model::Integrator::hht) {
      const JsonValue value =
          alpha ? *alpha : analysis.at("alpha", "HHT alpha in [-1/3, 0], required with hht");
      spec.alpha = value.number("HHT alpha");
      if (!(spec.alpha >= -1.0 / 3.0 && spec.alpha <= 0.0)) {
        throw value.error("HHT alpha must be in [-1/3, 0] (got " +
                          describe_json_value(value.json()) + ")");
      }
    } else if (alpha) {
      throw alpha->error("alpha applies to the hht integrator only; remove it or set "
                         "\"integrator\": \"hht\"");
    }
    if (const auto free_vibration = analysis.find("free_vibration"))
      spec.free_vibration = non_negative(*free_vibration, "free vibration after the record", " s");
    if (const auto drift_limit = analysis.find("drift_limit")) {
      spec.drift_limit = drift_limit->number("story drift ratio limit");
      if (!(spec.drift_limit > 0.0 && spec.drift_limit <= 1.0)) {
        throw drift_limit->error("the drift limit must be in (0, 1] (got " +
                                 describe_json_value(drift_limit->json()) + ")");
      }
    }
  }

  void read_ground_motion(const JsonValue& ground_motion) {
    ground_motion.expect_object({"directions"}, "a ground motion object {\"directions\"}");
    const auto directions = ground_motion.find("directions");
    if (!directions)
      return;
    const std::size_t count = directions->expect_array(3, "ground motion directions");
    if (count == 0)
      throw directions->error(
          "expected one to three directions (\"x\", \"y\", \"z\" for the vertical)");
    spec_.ground_directions.clear();
    for (std::size_t index = 0; index < count; ++index) {
      const JsonValue entry = directions->element(index);
      const auto direction = one_of<model::GroundDirection>(entry, "ground motion direction",
                                                            {{"x", model::GroundDirection::x},
                                                             {"y", model::GroundDirection::y},
                                                             {"z", model::GroundDirection::z}});
      if (direction == model::GroundDirection::y &&
          spec_.dimension == model::FrameDimension::planar) {
        throw entry.error("a planar model (dimension 2, X-Z plane) takes ground motion along "
                          "\"x\" and \"z\" only");
      }
      if (std::find(spec_.ground_directions.begin(), spec_.ground_directions.end(), direction) !=
          spec_.ground_directions.end()) {
        throw entry.error("direction listed twice");
      }
      spec_.ground_directions.push_back(direction);
    }
  }

  /// A name unique among `names` (stories or floors).
  static std::string unique_name(const JsonValue& value, std::set<std::string>& names) {
    const std::string name = value.string("name");
    if (!names.insert(name).second)
      throw value.error("the name \"" + name + "\" is used twice; expected unique names");
    return name;
  }

  void read_stories(const JsonValue& stories, const NodeTable& nodes) {
    const std::size_t count = stories.expect_array(SIZE_MAX, "stories {name, bottom, top}");
    std::set<std::string> names;
    for (std::size_t index = 0; index < count; ++index) {
      const JsonValue story = stories.element(index);
      story.expect_object({"name", "bottom", "top"},
                          "a story {\"name\", \"bottom\": node id, \"top\": node id}");
      model::StorySpec spec;
      spec.name = unique_name(story.at("name", "the story's name"), names);
      const std::string who = "story \"" + spec.name + "\"";
      spec.bottom = nodes.reference(story.at("bottom", "its bottom reference node"), who);
      const JsonValue top = story.at("top", "its top reference node");
      spec.top = nodes.reference(top, who);
      const double bottom_z = spec_.node(spec.bottom).coordinates.z();
      const double top_z = spec_.node(spec.top).coordinates.z();
      if (!(top_z > bottom_z)) {
        throw top.error(who + ": its top node " + std::to_string(spec.top) +
                        " (Z = " + millimetres(top_z) + ") must be above its bottom node " +
                        std::to_string(spec.bottom) + " (Z = " + millimetres(bottom_z) + ")");
      }
      spec_.stories.push_back(std::move(spec));
    }
  }

  void read_floors(const JsonValue& floors, const NodeTable& nodes) {
    const std::size_t count = floors.expect_array(SIZE_MAX, "floors {name, node}");
    std::set<std::string> names;
    for (std::size_t index = 0; index < count; ++index) {
      const JsonValue floor = floors.element(index);
      floor.expect_object({"name", "node"}, "a floor {\"name\", \"node\": node id}");
      model::FloorSpec spec;
      spec.name = unique_name(floor.at("name", "the floor's name"), names);
      spec.node =
          nodes.reference(floor.at("node", "the floor's node"), "floor \"" + spec.name + "\"");
      spec_.floors.push_back(std::move(spec));
    }
  }

  void read_recorders(const JsonValue& recorders) {
    recorders.expect_object({"drifts", "floor_accelerations", "base_shear", "energy", "braces"},
                            "a recorders object {drifts, floor_accelerations, base_shear, "
                            "energy, braces}");
    model::RecorderSpec& spec = spec_.recorders;
    if (const auto drifts = recorders.find("drifts")) {
      spec.drifts = boolean(*drifts, "record story drifts");
      if (spec.drifts && spec_.stories.empty())
        throw drifts->error("story drifts need stories: define them in /stories");
    }
    if (const auto accelerations = recorders.find("floor_accelerations")) {
      spec.floor_accelerations = boolean(*accelerations, "record absolute floor accelerations");
      if (spec.floor_accelerations && spec_.floors.empty())
        throw accelerations->error("floor accelerations need floors: define them in /floors");
    }
    if (const auto base_shear = recorders.find("base_shear"))
      spec.base_shear = boolean(*base_shear, "record the base shear");
    if (const auto energy = recorders.find("energy"))
      spec.energy = boolean(*energy, "record the energy balance");
    if (const auto braces = recorders.find("braces"))
      read_brace_recorders(*braces);
  }

  void read_brace_recorders(const JsonValue& braces) {
    model::RecorderSpec& spec = spec_.recorders;
    if (braces.json().is_string()) {
      spec.all_braces =
          one_of<bool>(braces, "brace recorder choice", {{"all", true}, {"none", false}});
      return;
    }
    const std::size_t count = braces.expect_array(SIZE_MAX, "\"all\", \"none\" or brb element ids");
    for (std::size_t index = 0; index < count; ++index) {
      const JsonValue entry = braces.element(index);
      const int id = positive_id(entry, "element id");
      const auto element = std::find_if(spec_.elements.begin(), spec_.elements.end(),
                                        [id](const auto& candidate) { return candidate.id == id; });
      if (element == spec_.elements.end()) {
        throw entry.error("no element has id " + std::to_string(id) +
                          "; expected the id of a brb element of /elements");
      }
      if (!std::holds_alternative<model::BraceElementSpec>(element->kind)) {
        throw entry.error("element " + std::to_string(id) +
                          " is not a brb element; expected the id of a brb element");
      }
      if (std::find(spec.brace_ids.begin(), spec.brace_ids.end(), id) != spec.brace_ids.end())
        throw entry.error("element " + std::to_string(id) + " is listed twice");
      spec.brace_ids.push_back(id);
    }
  }

  /// Every analysis of a frame file is dynamic: it needs mass, and mass along each ground
  /// motion direction (else the record exerts no force).
  void check_mass() const {
    std::array<double, model::kDofPerNode> total{};
    for (const auto& entry : spec_.masses) {
      for (std::size_t dof = 0; dof < model::kDofPerNode; ++dof)
        total[dof] += entry.mass[dof];
    }
    if (std::all_of(total.begin(), total.end(), [](double mass) { return mass == 0.0; })) {
      throw InputError(source_, "/masses",
                       "zero mass with a dynamic analysis: the model needs masses (expected "
                       "nodal masses > 0 in /masses)");
    }
    const auto directions = root_.find("ground_motion");
    for (std::size_t index = 0; index < spec_.ground_directions.size(); ++index) {
      const auto direction = spec_.ground_directions[index];
      const Dof dof = direction == model::GroundDirection::x   ? Dof::ux
                      : direction == model::GroundDirection::y ? Dof::uy
                                                               : Dof::uz;
      if (!(total[dof] > 0.0)) {
        const std::string location =
            directions ? directions->path() + "/directions/" + std::to_string(index)
                       : std::string("/masses");
        throw InputError(source_, location,
                         "no translational mass along " + std::string(kDofNames[dof]) +
                             ", the direction of the ground motion: expected nodal masses > 0 "
                             "along it in /masses");
      }
    }
  }

  const JsonValue& root_;
  std::string source_;
  std::filesystem::path base_directory_;
  model::FrameSpec spec_;
};

} // namespace

model::FrameSpec parse_frame(std::string_view json_text, const std::string& source,
                             const std::filesystem::path& base_directory) {
  const json document = parse_json(json_text, source);
  const JsonValue root(document, source);
  return FrameReader(root, base_directory).read();
}

model::FrameSpec read_frame(const std::filesystem::path& file) {
  return parse_frame(read_text_file(file), file.string(), file.parent_path());
}

} // namespace brb::io
