// Frame model files: the schema of the README ("Frame model files") mapped onto
// model::FrameSpec, the defaults, and every rejected input reported as an InputError naming
// the file, the JSON path and what was expected.
#include "brb/io/frame_input.hpp"
#include "brb/io/input_error.hpp"
#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <functional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace brb::io {
namespace {

using nlohmann::json;

/// A bare brace whose lengths add up to 5000 mm: 3000 + 2 x 200 + 2 x 800.
constexpr std::string_view kBraceFile = R"({
  "name": "story 1",
  "core": {
    "section": {"shape": "rectangle", "width": 100, "depth": 20},
    "steel": {"E": 200000, "nu": 0.3, "fy": 262, "H_kin": 2000, "H_iso": 0},
    "yielding_length": 3000
  },
  "transition": {"length": 200, "section": {"shape": "rectangle", "width": 140, "depth": 20}},
  "connection": {"length": 800, "section": {"shape": "rectangle", "width": 180, "depth": 20}}
})";

/// A small planar model giving every key of the schema (with comments, which are allowed).
/// Both braces are diagonals of a 3000 x 4000 mm bay: 5000 mm, the brace file's length.
constexpr std::string_view kFullModel = R"({
  // a one-bay, one-storey frame with every kind of element
  "title": "test frame",
  "units": {"length": "mm", "force": "N", "mass": "tonne"},
  "dimension": 2,
  "nodes": [
    {"id": 1, "xyz": [0, 0, 0]}, {"id": 2, "xyz": [3000, 0, 0]},
    {"id": 3, "xyz": [6000, 0, 0]}, {"id": 4, "xyz": [6000, 0, 0]},
    {"id": 11, "xyz": [0, 0, 4000]}, {"id": 12, "xyz": [3000, 0, 4000]},
    {"id": 13, "xyz": [6000, 0, 4000]}
  ],
  "supports": [{"node": 1, "fix": "fixed"}, {"node": 2, "fix": "pinned"},
               {"node": 3, "fix": ["ux", "uz", "ry"]}],
  "constraints": [
    {"type": "equal_dof", "master": 11, "slave": 12, "dofs": ["ux"]},
    /* a slab tying node 13 to node 11 */
    {"type": "rigid_diaphragm", "master": 11, "nodes": [13]}
  ],
  "masses": [{"node": 11, "mass": 50.0}, {"node": 12, "mass": [40, 41, 42, 0, 1e6, 0]}],
  "sections": {
    "W14X90": {"E": 200000, "G": 77000, "A": 17100, "Iy": 4.16e8, "Iz": 1.48e8, "J": 1.7e6}
  },
  "materials": {
    "gap_spring": {"law": "elastic", "E": 1000},
    "hinge_steel": {"law": "steel", "E": 210000, "nu": 0.3, "fy": 300, "H_kin": 1000, "H_iso": 0},
    "grout": {"law": "mortar", "E": 17520, "nu": 0.2, "fc": 50, "ft": 5, "Gf": 0.1}
  },
  "elements": [
    {"id": 1, "type": "elastic_beam", "nodes": [1, 11], "section": "W14X90",
     "geometry": "pdelta", "orientation": [-1, 0, 0]},
    {"id": 2, "type": "elastic_beam", "nodes": [11, 12], "section": "W14X90"},
    {"id": 3, "type": "truss", "nodes": [12, 13], "area": 1000, "material": "gap_spring"},
    {"id": 4, "type": "spring", "nodes": [3, 4], "dofs": {"ux": "gap_spring", "ry": "hinge_steel"}},
    {"id": 5, "type": "fiber_beam", "nodes": [4, 13],
     "section": {"shape": "circle", "diameter": 300, "fibers": [3, 12]},
     "steel": {"E": 200000, "nu": 0.3, "fy": 345, "H_kin": 2000, "H_iso": 100},
     "subdivisions": 4, "integration": {"rule": "gauss_legendre", "points": 2},
     "orientation": [0, 1, 0]},
    {"id": 6, "type": "brb", "nodes": [1, 12], "brace": "braces/story1.json",
     "fidelity": "full", "mode": "expanded"},
    {"id": 7, "type": "brb", "nodes": [2, 11], "brace": {
       "name": "inline",
       "core": {"section": {"shape": "rectangle", "width": 100, "depth": 20},
                "steel": {"E": 200000, "nu": 0.3, "fy": 262, "H_kin": 2000, "H_iso": 0},
                "yielding_length": 4000},
       "connection": {"length": 500, "section": {"shape": "rectangle", "width": 180, "depth": 20}}},
     "fidelity": "truss", "orientation": [0, 1, 0]}
  ],
  "gravity": {"from_masses": true, "loads": [{"node": 13, "force": [0, 0, -5e5, 0, 0, 0]}],
              "steps": 5},
  "damping": {"type": "rayleigh", "modes": [1, 3], "ratios": [0.02, 0.05],
              "stiffness": "initial", "exclude_braces": false},
  "analysis": {"integrator": "hht", "dt": 0.01, "alpha": -0.1, "free_vibration": 2.0,
               "drift_limit": 0.05},
  "ground_motion": {"directions": ["x"]},
  "stories": [{"name": "1", "bottom": 1, "top": 11}],
  "floors": [{"name": "roof", "node": 11}],
  "recorders": {"drifts": true, "floor_accelerations": true, "base_shear": false,
                "energy": true, "braces": [6]},
  "design": {"R": 8, "note": "documentation only"}
})";

/// The smallest valid model: one column with a mass on top, every optional key left out.
constexpr std::string_view kMinimalModel = R"({
  "dimension": 3,
  "nodes": [{"id": 1, "xyz": [0, 0, 0]}, {"id": 2, "xyz": [0, 0, 3000]}],
  "masses": [{"node": 2, "mass": 10}],
  "sections": {"S": {"E": 200000, "G": 77000, "A": 1000, "Iy": 1e7, "Iz": 1e7, "J": 1e5}},
  "elements": [{"id": 1, "type": "elastic_beam", "nodes": [1, 2], "section": "S"}]
})";

class FrameInputTest : public ::testing::Test {
protected:
  FrameInputTest() {
    std::filesystem::create_directories(scratch_.path() / "braces");
    scratch_.write("braces/story1.json", kBraceFile);
  }

  std::filesystem::path write_model(std::string_view text) const {
    return scratch_.write("frame.json", text);
  }
  std::filesystem::path write_model(const json& document) const {
    return scratch_.write("frame.json", document.dump(2));
  }

  testing::ScratchDirectory scratch_;
};

template <class Kind> const Kind& kind_of(const model::FrameElementSpec& element) {
  EXPECT_TRUE(std::holds_alternative<Kind>(element.kind)) << "element " << element.id;
  return std::get<Kind>(element.kind);
}

TEST_F(FrameInputTest, FullModelParsesWithEveryFieldAsWritten) {
  const model::FrameSpec spec = read_frame(write_model(kFullModel));

  EXPECT_EQ(spec.title, "test frame");
  EXPECT_EQ(spec.dimension, model::FrameDimension::planar);
  ASSERT_EQ(spec.nodes.size(), 7u);
  EXPECT_EQ(spec.nodes[5].id, 12);
  EXPECT_EQ(spec.nodes[5].coordinates, element::Vector3(3000, 0, 4000));

  ASSERT_EQ(spec.supports.size(), 3u);
  EXPECT_EQ(spec.supports[0].node, 1);
  EXPECT_EQ(spec.supports[0].fixed, (std::array<bool, 6>{true, true, true, true, true, true}));
  EXPECT_EQ(spec.supports[1].fixed, (std::array<bool, 6>{true, true, true, false, false, false}));
  EXPECT_EQ(spec.supports[2].node, 3);
  EXPECT_EQ(spec.supports[2].fixed, (std::array<bool, 6>{true, false, true, false, true, false}));

  ASSERT_EQ(spec.equal_dofs.size(), 1u);
  EXPECT_EQ(spec.equal_dofs[0].master, 11);
  EXPECT_EQ(spec.equal_dofs[0].slave, 12);
  EXPECT_EQ(spec.equal_dofs[0].dofs, std::vector<model::Dof>{model::ux});
  ASSERT_EQ(spec.rigid_diaphragms.size(), 1u);
  EXPECT_EQ(spec.rigid_diaphragms[0].master, 11);
  EXPECT_EQ(spec.rigid_diaphragms[0].slaves, std::vector<int>{13});

  ASSERT_EQ(spec.masses.size(), 2u);
  EXPECT_EQ(spec.masses[0].node, 11);
  EXPECT_EQ(spec.masses[0].mass, (model::NodalMass{50, 50, 50, 0, 0, 0}));
  EXPECT_EQ(spec.masses[1].mass, (model::NodalMass{40, 41, 42, 0, 1e6, 0}));

  ASSERT_EQ(spec.sections.size(), 1u);
  const model::ElasticSectionSpec& w14 = spec.sections.at("W14X90");
  EXPECT_EQ(w14.youngs_modulus, 200000);
  EXPECT_EQ(w14.shear_modulus, 77000);
  EXPECT_EQ(w14.area, 17100);
  EXPECT_EQ(w14.inertia_y, 4.16e8);
  EXPECT_EQ(w14.inertia_z, 1.48e8);
  EXPECT_EQ(w14.torsion_constant, 1.7e6);

  ASSERT_EQ(spec.materials.size(), 3u);
  EXPECT_EQ(std::get<model::ElasticLaw>(spec.materials.at("gap_spring")).youngs_modulus, 1000);
  const auto& hinge = std::get<material::SteelParameters>(spec.materials.at("hinge_steel"));
  EXPECT_EQ(hinge.youngs_modulus, 210000);
  EXPECT_EQ(hinge.yield_stress, 300);
  EXPECT_EQ(hinge.kinematic_hardening, 1000);
  EXPECT_FALSE(hinge.damage.has_value());
  const auto& grout = std::get<material::MortarParameters>(spec.materials.at("grout"));
  EXPECT_EQ(grout.youngs_modulus, 17520);
  EXPECT_EQ(grout.compressive_strength, 50);
  EXPECT_EQ(grout.tensile_strength, 5);
  EXPECT_EQ(grout.fracture_energy, 0.1);

  ASSERT_EQ(spec.elements.size(), 7u);
  const auto& column = kind_of<model::ElasticBeamSpec>(spec.elements[0]);
  EXPECT_EQ(spec.elements[0].id, 1);
  EXPECT_EQ(spec.elements[0].nodes, (std::array<int, 2>{1, 11}));
  EXPECT_EQ(column.section_name, "W14X90");
  EXPECT_EQ(column.section.inertia_y, 4.16e8);
  EXPECT_EQ(column.geometry, model::BeamGeometry::pdelta);
  ASSERT_TRUE(column.orientation.has_value());
  EXPECT_EQ(*column.orientation, element::Vector3(-1, 0, 0));
  const auto& beam = kind_of<model::ElasticBeamSpec>(spec.elements[1]);
  EXPECT_EQ(beam.geometry, model::BeamGeometry::linear);
  EXPECT_FALSE(beam.orientation.has_value());

  const auto& truss = kind_of<model::TrussSpec>(spec.elements[2]);
  EXPECT_EQ(truss.area, 1000);
  EXPECT_EQ(truss.material.name, "gap_spring");
  EXPECT_EQ(std::get<model::ElasticLaw>(truss.material.law).youngs_modulus, 1000);

  const auto& spring = kind_of<model::SpringSpec>(spec.elements[3]);
  EXPECT_EQ(spec.elements[3].nodes, (std::array<int, 2>{3, 4}));
  ASSERT_TRUE(spring.dofs[model::ux].has_value());
  EXPECT_EQ(spring.dofs[model::ux]->name, "gap_spring");
  ASSERT_TRUE(spring.dofs[model::ry].has_value());
  EXPECT_EQ(spring.dofs[model::ry]->name, "hinge_steel");
  EXPECT_EQ(std::get<material::SteelParameters>(spring.dofs[model::ry]->law).yield_stress, 300);
  for (const model::Dof dof : {model::uy, model::uz, model::rx, model::rz})
    EXPECT_FALSE(spring.dofs[dof].has_value()) << dof;

  const auto& fiber = kind_of<model::FiberBeamSpec>(spec.elements[4]);
  EXPECT_EQ(fiber.section.shape, model::SectionShape::circle);
  EXPECT_EQ(fiber.section.diameter, 300);
  EXPECT_EQ(fiber.section.fibers_a, 3);
  EXPECT_EQ(fiber.section.fibers_b, 12);
  EXPECT_EQ(fiber.steel.yield_stress, 345);
  EXPECT_EQ(fiber.steel.isotropic_hardening, 100);
  EXPECT_EQ(fiber.subdivisions, 4);
  EXPECT_EQ(fiber.integration_rule, element::IntegrationRule::gauss_legendre);
  EXPECT_EQ(fiber.integration_points, 2);
  EXPECT_EQ(fiber.orientation, element::Vector3(0, 1, 0));

  const auto& from_file = kind_of<model::BraceElementSpec>(spec.elements[5]);
  EXPECT_EQ(from_file.brace.name, "story 1");
  EXPECT_EQ(from_file.brace.yielding_length, 3000);
  EXPECT_EQ(from_file.brace.total_length(), 5000);
  EXPECT_EQ(from_file.fidelity, model::BraceFidelity::full);
  EXPECT_EQ(from_file.mode, model::ElementMode::expanded);
  EXPECT_EQ(from_file.source_file, scratch_.path() / "braces/story1.json");
  EXPECT_FALSE(from_file.orientation.has_value());
  const auto& inline_brace = kind_of<model::BraceElementSpec>(spec.elements[6]);
  EXPECT_EQ(inline_brace.brace.name, "inline");
  EXPECT_EQ(inline_brace.brace.total_length(), 5000);
  EXPECT_FALSE(inline_brace.brace.transition.has_value());
  EXPECT_EQ(inline_brace.fidelity, model::BraceFidelity::truss);
  EXPECT_EQ(inline_brace.mode, model::ElementMode::condensed);
  EXPECT_TRUE(inline_brace.source_file.empty());
  EXPECT_EQ(inline_brace.orientation, element::Vector3(0, 1, 0));

  ASSERT_TRUE(spec.gravity.has_value());
  EXPECT_TRUE(spec.gravity->from_masses);
  ASSERT_EQ(spec.gravity->loads.size(), 1u);
  EXPECT_EQ(spec.gravity->loads[0].node, 13);
  EXPECT_EQ(spec.gravity->loads[0].force, (std::array<double, 6>{0, 0, -5e5, 0, 0, 0}));
  EXPECT_EQ(spec.gravity->steps, 5);

  ASSERT_TRUE(spec.damping.has_value());
  const auto& rayleigh = std::get<model::RayleighDampingSpec>(*spec.damping);
  EXPECT_EQ(rayleigh.modes, (std::array<int, 2>{1, 3}));
  EXPECT_EQ(rayleigh.ratios, (std::array<double, 2>{0.02, 0.05}));
  EXPECT_FALSE(rayleigh.exclude_braces);

  EXPECT_EQ(spec.analysis.integrator, model::Integrator::hht);
  EXPECT_EQ(spec.analysis.dt, 0.01);
  EXPECT_EQ(spec.analysis.alpha, -0.1);
  EXPECT_EQ(spec.analysis.free_vibration, 2.0);
  EXPECT_EQ(spec.analysis.drift_limit, 0.05);
  EXPECT_EQ(spec.ground_directions, std::vector<model::GroundDirection>{model::GroundDirection::x});

  ASSERT_EQ(spec.stories.size(), 1u);
  EXPECT_EQ(spec.stories[0].name, "1");
  EXPECT_EQ(spec.stories[0].bottom, 1);
  EXPECT_EQ(spec.stories[0].top, 11);
  ASSERT_EQ(spec.floors.size(), 1u);
  EXPECT_EQ(spec.floors[0].name, "roof");
  EXPECT_EQ(spec.floors[0].node, 11);

  EXPECT_TRUE(spec.recorders.drifts);
  EXPECT_TRUE(spec.recorders.floor_accelerations);
  EXPECT_FALSE(spec.recorders.base_shear);
  EXPECT_TRUE(spec.recorders.energy);
  EXPECT_FALSE(spec.recorders.all_braces);
  EXPECT_EQ(spec.recorders.brace_ids, std::vector<int>{6});
}

TEST_F(FrameInputTest, ParseFrameResolvesBraceFilesAgainstTheBaseDirectory) {
  const model::FrameSpec spec = parse_frame(kFullModel, "in-memory.json", scratch_.path());
  EXPECT_EQ(kind_of<model::BraceElementSpec>(spec.elements[5]).brace.name, "story 1");
}

TEST_F(FrameInputTest, OmittedKeysTakeTheDocumentedDefaults) {
  const model::FrameSpec spec = read_frame(write_model(kMinimalModel));
  EXPECT_EQ(spec.title, "");
  EXPECT_EQ(spec.dimension, model::FrameDimension::spatial);
  EXPECT_TRUE(spec.supports.empty());
  EXPECT_TRUE(spec.equal_dofs.empty());
  EXPECT_TRUE(spec.rigid_diaphragms.empty());
  EXPECT_TRUE(spec.materials.empty());
  const auto& column = kind_of<model::ElasticBeamSpec>(spec.elements.at(0));
  EXPECT_EQ(column.geometry, model::BeamGeometry::linear);
  EXPECT_FALSE(column.orientation.has_value());
  EXPECT_FALSE(spec.gravity.has_value());
  EXPECT_FALSE(spec.damping.has_value());
  EXPECT_EQ(spec.analysis.integrator, model::Integrator::newmark);
  EXPECT_FALSE(spec.analysis.dt.has_value());
  EXPECT_EQ(spec.analysis.alpha, 0.0);
  EXPECT_EQ(spec.analysis.free_vibration, 0.0);
  EXPECT_EQ(spec.analysis.drift_limit, 0.10);
  EXPECT_EQ(spec.ground_directions, std::vector<model::GroundDirection>{model::GroundDirection::x});
  EXPECT_TRUE(spec.stories.empty());
  EXPECT_TRUE(spec.floors.empty());
  EXPECT_FALSE(spec.recorders.drifts || spec.recorders.floor_accelerations ||
               spec.recorders.base_shear || spec.recorders.energy || spec.recorders.all_braces);
  EXPECT_TRUE(spec.recorders.brace_ids.empty());
}

TEST_F(FrameInputTest, DefaultsOfBracesGravityDampingAndRecorders) {
  json document = json::parse(kFullModel, nullptr, true, true);
  document["elements"][5].erase("fidelity");
  document["elements"][5].erase("mode");
  document["gravity"] = {{"loads", json::array()}};
  document["damping"] = {{"type", "rayleigh"}, {"modes", {1, 2}}, {"ratios", {0.05, 0.05}}};
  document["recorders"] = {{"braces", "all"}};
  const model::FrameSpec spec = read_frame(write_model(document));
  const auto& brace = kind_of<model::BraceElementSpec>(spec.elements[5]);
  EXPECT_EQ(brace.fidelity, model::BraceFidelity::automatic);
  EXPECT_EQ(brace.mode, model::ElementMode::condensed);
  EXPECT_FALSE(spec.gravity->from_masses);
  EXPECT_EQ(spec.gravity->steps, 10);
  EXPECT_TRUE(std::get<model::RayleighDampingSpec>(*spec.damping).exclude_braces);
  EXPECT_TRUE(spec.recorders.all_braces);
  EXPECT_FALSE(spec.recorders.drifts);
}

TEST_F(FrameInputTest, ABraceWithinOneMillimetreOfTheNodeDistanceIsAccepted) {
  // 4000.9 + 2 x 500 = 5000.9 mm between nodes 5000 mm apart: within the 1 mm of the schema.
  json document = json::parse(kFullModel, nullptr, true, true);
  document["elements"][6]["brace"]["core"]["yielding_length"] = 4000.9;
  const model::FrameSpec spec = read_frame(write_model(document));
  EXPECT_DOUBLE_EQ(kind_of<model::BraceElementSpec>(spec.elements[6]).brace.total_length(), 5000.9);
}

TEST_F(FrameInputTest, ModalDampingAndTheExplicitIntegrator) {
  json document = json::parse(kMinimalModel);
  document["damping"] = {{"type", "modal"}, {"ratio", 0.03}, {"modes", 6}};
  document["analysis"] = {{"integrator", "explicit"}};
  const model::FrameSpec spec = read_frame(write_model(document));
  const auto& modal = std::get<model::ModalDampingSpec>(*spec.damping);
  EXPECT_EQ(modal.ratio, 0.03);
  EXPECT_EQ(modal.modes, 6);
  EXPECT_EQ(spec.analysis.integrator, model::Integrator::explicit_central_difference);
}

TEST_F(FrameInputTest, ASpatialModelTakesTwoGroundMotionDirections) {
  json document = json::parse(kMinimalModel);
  document["ground_motion"] = {{"directions", {"x", "y"}}};
  const model::FrameSpec spec = read_frame(write_model(document));
  EXPECT_EQ(spec.ground_directions, (std::vector<model::GroundDirection>{
                                        model::GroundDirection::x, model::GroundDirection::y}));
}

/// A model made invalid in one place, the JSON path the error must name and phrases the
/// message must contain (what was expected, the ids involved).
struct InvalidFrameCase {
  std::string name;
  std::function<void(json&)> break_model;
  std::string path;
  std::vector<std::string> phrases;
};

void PrintTo(const InvalidFrameCase& invalid, std::ostream* out) {
  *out << invalid.name;
}

class InvalidFrameTest : public FrameInputTest,
                         public ::testing::WithParamInterface<InvalidFrameCase> {};

TEST_P(InvalidFrameTest, IsRejectedNamingFilePathAndExpectation) {
  const InvalidFrameCase& invalid = GetParam();
  json document = json::parse(kFullModel, nullptr, true, true);
  invalid.break_model(document);
  const auto file = write_model(document);
  try {
    read_frame(file);
    FAIL() << invalid.name << " was accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(error.file(), file.string());
    EXPECT_EQ(error.location(), invalid.path) << message;
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    EXPECT_NE(message.find(invalid.path), std::string::npos) << message;
    for (const auto& phrase : invalid.phrases)
      EXPECT_NE(message.find(phrase), std::string::npos)
          << "no \"" << phrase << "\" in " << message;
  }
}

/// Sets the element with id `id` to `element`.
json& element_with_id(json& document, int id) {
  for (auto& element : document["elements"]) {
    if (element["id"] == id)
      return element;
  }
  throw std::logic_error("no element " + std::to_string(id));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, InvalidFrameTest,
    ::testing::Values(
        InvalidFrameCase{"dangling node of an element",
                         [](json& d) { d["elements"][2]["nodes"][1] = 99; },
                         "/elements/2/nodes/1",
                         {"element 3", "node 99", "does not exist"}},
        InvalidFrameCase{"dangling node of a support",
                         [](json& d) { d["supports"][1]["node"] = 98; },
                         "/supports/1/node",
                         {"node 98", "does not exist"}},
        InvalidFrameCase{"dangling master of a constraint",
                         [](json& d) { d["constraints"][0]["master"] = 97; },
                         "/constraints/0/master",
                         {"equal_dof", "node 97"}},
        InvalidFrameCase{"dangling slave of a rigid diaphragm",
                         [](json& d) { d["constraints"][1]["nodes"][0] = 96; },
                         "/constraints/1/nodes/0",
                         {"rigid diaphragm", "node 96"}},
        InvalidFrameCase{"dangling node of a mass",
                         [](json& d) { d["masses"][0]["node"] = 95; },
                         "/masses/0/node",
                         {"node 95"}},
        InvalidFrameCase{"dangling node of a gravity load",
                         [](json& d) { d["gravity"]["loads"][0]["node"] = 94; },
                         "/gravity/loads/0/node",
                         {"gravity load", "node 94"}},
        InvalidFrameCase{"dangling node of a story",
                         [](json& d) { d["stories"][0]["top"] = 93; },
                         "/stories/0/top",
                         {"story \"1\"", "node 93"}},
        InvalidFrameCase{"dangling node of a floor",
                         [](json& d) { d["floors"][0]["node"] = 92; },
                         "/floors/0/node",
                         {"floor \"roof\"", "node 92"}},
        InvalidFrameCase{"duplicate node id",
                         [](json& d) { d["nodes"][3]["id"] = 2; },
                         "/nodes/3/id",
                         {"duplicate node id 2", "/nodes/1", "unique"}},
        InvalidFrameCase{"duplicate element id",
                         [](json& d) { d["elements"][4]["id"] = 2; },
                         "/elements/4/id",
                         {"duplicate element id 2", "/elements/1", "unique"}},
        InvalidFrameCase{
            "unknown element type",
            [](json& d) { d["elements"][2]["type"] = "cable"; },
            "/elements/2/type",
            {"unknown element type \"cable\"", "elastic_beam, truss, spring, fiber_beam, brb"}},
        InvalidFrameCase{"zero mass with a dynamic analysis",
                         [](json& d) { d.erase("masses"); },
                         "/masses",
                         {"zero mass with a dynamic analysis", "needs masses"}},
        InvalidFrameCase{"masses all zero",
                         [](json& d) {
                           d["masses"] = json::array({{{"node", 11}, {"mass", 0.0}}});
                         },
                         "/masses",
                         {"zero mass with a dynamic analysis"}},
        InvalidFrameCase{"dt zero",
                         [](json& d) { d["analysis"]["dt"] = 0.0; },
                         "/analysis/dt",
                         {"must be > 0 s", "got 0"}},
        InvalidFrameCase{"dt negative",
                         [](json& d) { d["analysis"]["dt"] = -0.01; },
                         "/analysis/dt",
                         {"must be > 0 s", "got -0.01"}},
        InvalidFrameCase{"alpha below -1/3",
                         [](json& d) { d["analysis"]["alpha"] = -0.4; },
                         "/analysis/alpha",
                         {"[-1/3, 0]", "got -0.4"}},
        InvalidFrameCase{"alpha above 0",
                         [](json& d) { d["analysis"]["alpha"] = 0.1; },
                         "/analysis/alpha",
                         {"[-1/3, 0]", "got 0.1"}},
        InvalidFrameCase{"alpha missing with hht",
                         [](json& d) { d["analysis"].erase("alpha"); },
                         "/analysis/alpha",
                         {"missing required key", "required with hht"}},
        InvalidFrameCase{"alpha with newmark",
                         [](json& d) { d["analysis"]["integrator"] = "newmark"; },
                         "/analysis/alpha",
                         {"hht integrator only"}},
        InvalidFrameCase{"missing brace file",
                         [](json& d) { element_with_id(d, 6)["brace"] = "braces/none.json"; },
                         "/elements/5/brace",
                         {"braces/none.json", "missing or invalid", "does not exist"}},
        InvalidFrameCase{
            "brace length mismatch",
            [](json& d) { element_with_id(d, 7)["brace"]["core"]["yielding_length"] = 4010.5; },
            "/elements/6/brace",
            {"5010.5 mm", "5000 mm", "nodes 2 and 11", "within 1 mm"}},
        InvalidFrameCase{"unknown top-level key",
                         [](json& d) { d["dampng"] = json::object(); },
                         "/dampng",
                         {"unknown key", "damping", "design"}},
        InvalidFrameCase{"unknown key of an element",
                         [](json& d) { d["elements"][2]["areaa"] = 10; },
                         "/elements/2/areaa",
                         {"unknown key", "area, material"}},
        InvalidFrameCase{"unknown section",
                         [](json& d) { d["elements"][1]["section"] = "W8"; },
                         "/elements/1/section",
                         {"unknown section \"W8\"", "W14X90"}},
        InvalidFrameCase{"unknown material",
                         [](json& d) { d["elements"][3]["dofs"]["ry"] = "rubber"; },
                         "/elements/3/dofs/ry",
                         {"unknown material \"rubber\"", "gap_spring, grout, hinge_steel"}},
        InvalidFrameCase{"zero-length element",
                         [](json& d) {
                           d["elements"][4]["nodes"] = {3, 4};
                         },
                         "/elements/4/nodes",
                         {"element 5", "zero length", "nodes 3 and 4"}},
        InvalidFrameCase{"element on one node",
                         [](json& d) {
                           d["elements"][2]["nodes"] = {12, 12};
                         },
                         "/elements/2/nodes",
                         {"element 3", "two different nodes"}},
        InvalidFrameCase{"story top not above its bottom",
                         [](json& d) {
                           d["stories"][0] = {{"name", "1"}, {"bottom", 11}, {"top", 12}};
                         },
                         "/stories/0/top",
                         {"must be above", "Z = 4000 mm"}},
        InvalidFrameCase{"unsupported length unit",
                         [](json& d) { d["units"]["length"] = "m"; },
                         "/units/length",
                         {"unsupported length unit \"m\"", "\"mm\""}},
        InvalidFrameCase{"negative mass",
                         [](json& d) { d["masses"][1]["mass"][2] = -1.0; },
                         "/masses/1/mass/2",
                         {">= 0"}},
        InvalidFrameCase{"section area zero",
                         [](json& d) { d["sections"]["W14X90"]["A"] = 0; },
                         "/sections/W14X90/A",
                         {"must be > 0 mm^2"}},
        InvalidFrameCase{"truss area negative",
                         [](json& d) { d["elements"][2]["area"] = -5; },
                         "/elements/2/area",
                         {"must be > 0 mm^2"}},
        InvalidFrameCase{"elastic law E zero",
                         [](json& d) { d["materials"]["gap_spring"]["E"] = 0; },
                         "/materials/gap_spring/E",
                         {"must be > 0"}},
        InvalidFrameCase{"steel law out of range",
                         [](json& d) { d["materials"]["hinge_steel"]["fy"] = -3; },
                         "/materials/hinge_steel/fy",
                         {"> 0"}},
        InvalidFrameCase{"unknown key of a steel law",
                         [](json& d) { d["materials"]["hinge_steel"]["fyy"] = 300; },
                         "/materials/hinge_steel/fyy",
                         {"unknown key", "law, units, E, nu, fy"}},
        InvalidFrameCase{"lc in a steel law",
                         [](json& d) { d["materials"]["hinge_steel"]["lc"] = 10; },
                         "/materials/hinge_steel/lc",
                         {"unknown key"}},
        InvalidFrameCase{"mortar law without Gf",
                         [](json& d) { d["materials"]["grout"].erase("Gf"); },
                         "/materials/grout/Gf",
                         {"missing required key"}},
        InvalidFrameCase{"unknown law",
                         [](json& d) { d["materials"]["grout"]["law"] = "rubber"; },
                         "/materials/grout/law",
                         {"\"elastic\", \"steel\", \"mortar\""}},
        InvalidFrameCase{"drift limit above 1",
                         [](json& d) { d["analysis"]["drift_limit"] = 1.5; },
                         "/analysis/drift_limit",
                         {"(0, 1]"}},
        InvalidFrameCase{"damping ratio of 1",
                         [](json& d) { d["damping"]["ratios"][1] = 1.0; },
                         "/damping/ratios/1",
                         {"[0, 1)"}},
        InvalidFrameCase{"mode number 0",
                         [](json& d) { d["damping"]["modes"][0] = 0; },
                         "/damping/modes/0",
                         {"whole number >= 1"}},
        InvalidFrameCase{"current stiffness damping",
                         [](json& d) { d["damping"]["stiffness"] = "current"; },
                         "/damping/stiffness",
                         {"\"initial\""}},
        InvalidFrameCase{"gravity steps 0",
                         [](json& d) { d["gravity"]["steps"] = 0; },
                         "/gravity/steps",
                         {"whole number >= 1"}},
        InvalidFrameCase{
            "dimension 1", [](json& d) { d["dimension"] = 1; }, "/dimension", {"in [2, 3]"}},
        InvalidFrameCase{"planar node off the X-Z plane",
                         [](json& d) { d["nodes"][2]["xyz"][1] = 5.0; },
                         "/nodes/2/xyz/1",
                         {"X-Z plane", "got 5"}},
        InvalidFrameCase{"planar ground motion along y",
                         [](json& d) { d["ground_motion"]["directions"] = {"y"}; },
                         "/ground_motion/directions/0",
                         {"\"x\" and \"z\" only"}},
        InvalidFrameCase{"orientation parallel to the member",
                         [](json& d) { d["elements"][0]["orientation"] = {0, 0, 2}; },
                         "/elements/0/orientation",
                         {"parallel to the member"}},
        InvalidFrameCase{
            "invalid inline brace located in the frame file",
            [](json& d) { element_with_id(d, 7)["brace"]["core"]["steel"]["fy"] = -1; },
            "/elements/6/brace/core/steel/fy",
            {"> 0"}},
        InvalidFrameCase{"invalid fiber section located at the element",
                         [](json& d) { d["elements"][4]["section"]["width"] = 10; },
                         "/elements/4/section/width",
                         {"circle has no dimension \"width\""}},
        InvalidFrameCase{"invalid fiber steel located at the element",
                         [](json& d) { d["elements"][4]["steel"]["lc"] = 10; },
                         "/elements/4/steel/lc",
                         {"unknown key"}},
        InvalidFrameCase{"brace recorder of a beam",
                         [](json& d) { d["recorders"]["braces"] = {6, 2}; },
                         "/recorders/braces/1",
                         {"element 2 is not a brb element"}},
        InvalidFrameCase{"drift recorder without stories",
                         [](json& d) { d.erase("stories"); },
                         "/recorders/drifts",
                         {"need stories"}},
        InvalidFrameCase{
            "duplicate story name",
            [](json& d) { d["stories"].push_back({{"name", "1"}, {"bottom", 2}, {"top", 12}}); },
            "/stories/1/name",
            {"used twice"}}));

TEST_F(FrameInputTest, AnInvalidBraceFileIsReportedWithTheBraceReadersMessage) {
  scratch_.write("braces/bad.json", R"({"core": {"section": {"shape": "rectangle", "width": 100,
    "depth": 20}, "steel": {"E": 200000, "nu": 0.3, "fy": 262, "H_kin": 0, "H_iso": 0},
    "yielding_length": 5000}, "endz": "pinned"})");
  json document = json::parse(kFullModel, nullptr, true, true);
  document["elements"][5]["brace"] = "braces/bad.json";
  const auto file = write_model(document);
  try {
    read_frame(file);
    FAIL() << "accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(error.location(), "/elements/5/brace");
    // prefixed by the frame file and path, then the brace reader's message: its file and path
    EXPECT_TRUE(message.starts_with(file.string() + ": /elements/5/brace: ")) << message;
    EXPECT_NE(message.find((scratch_.path() / "braces/bad.json").string() + ": /endz: unknown key"),
              std::string::npos)
        << message;
  }
}

/// The example buildings of frames/ (frames/README.md) load with the reader; the counts are
/// compared with the file read as plain JSON.
TEST(FrameExamples, EveryExampleBuildingLoads) {
  const std::filesystem::path frames = std::filesystem::path(BRB_SOURCE_DIR) / "frames";
  for (const auto& [name, dimension] : {std::pair{"brbf3", model::FrameDimension::planar},
                                        std::pair{"brbf9", model::FrameDimension::planar},
                                        std::pair{"brbf4_3d", model::FrameDimension::spatial}}) {
    SCOPED_TRACE(name);
    const auto file = frames / name / "model.json";
    const model::FrameSpec spec = read_frame(file);
    const json document = json::parse(testing::read_file(file), nullptr, true, true);
    EXPECT_EQ(spec.dimension, dimension);
    EXPECT_EQ(spec.nodes.size(), document["nodes"].size());
    EXPECT_EQ(spec.stories.size(), document["stories"].size());
    EXPECT_EQ(spec.floors.size(), document["floors"].size());
    ASSERT_EQ(spec.elements.size(), document["elements"].size());
    std::size_t braces = 0;
    for (std::size_t index = 0; index < spec.elements.size(); ++index) {
      const std::string type = document["elements"][index]["type"];
      const auto* brace = std::get_if<model::BraceElementSpec>(&spec.elements[index].kind);
      EXPECT_EQ(brace != nullptr, type == "brb") << "element " << spec.elements[index].id;
      if (brace) {
        ++braces;
        EXPECT_EQ(brace->fidelity, model::BraceFidelity::automatic);
        EXPECT_TRUE(std::filesystem::exists(brace->source_file)) << brace->source_file;
        EXPECT_NEAR(brace->brace.total_length(), spec.element_length(spec.elements[index]),
                    kBraceLengthTolerance);
      }
    }
    EXPECT_GE(braces, 2 * spec.stories.size()); // two braces per braced bay and storey
    EXPECT_EQ(spec.ground_directions.size(), document["ground_motion"]["directions"].size());
  }
}

TEST_F(FrameInputTest, AMissingModelFileIsAnInputError) {
  EXPECT_THROW(read_frame(scratch_.path() / "none.json"), InputError);
}

} // namespace
} // namespace brb::io
