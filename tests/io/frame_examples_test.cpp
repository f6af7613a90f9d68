// The example buildings of frames/ (issue 5): each model.json (frame schema, written by
// frames/design.py) is checked for consistency before any solver runs it: ids, references,
// brace files (read by the brace reader) whose lengths match their work points, masses and
// gravity against the design's seismic weight, and the ELF numbers of its "design" block
// recomputed here from ASCE 7-16 (an independent computation of the script's formulas).
#include "brb/io/brace_input.hpp"
#include "brb/model/brace_model.hpp"
#include "brb/model/brace_spec.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <numeric>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace brb::io {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr double kGravity = 9806.65; // mm/s^2, the standard gravity design.py uses

const fs::path kFrames = fs::path(BRB_SOURCE_DIR) / "frames";

struct Example {
  std::string folder;
  int dimension;
  int storeys;
};

std::ostream& operator<<(std::ostream& out, const Example& example) {
  return out << example.folder;
}

json read_model(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  // Comments allowed, as the frame reader allows them.
  return json::parse(text.str(), nullptr, true, true);
}

using Point = std::array<double, 3>;

double distance(const Point& a, const Point& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

/// ASCE 7-16 Cs (Eqs 12.8-2 to 12.8-6) with the 11.4.8 exception 2 for site class D
/// (1.5 x Eq 12.8-3 for 1.5 Ts < T <= TL), written again from the standard.
double seismic_response_coefficient(const json& d) {
  const double sds = d.at("SDS"), sd1 = d.at("SD1"), period = d.at("T");
  const double r_over_ie = d.at("R").get<double>() / d.at("Ie").get<double>();
  const double ts = sd1 / sds, tl = d.at("TL"), s1 = d.at("site").at("S1");
  const double upper = sds / r_over_ie;
  double cs = upper;
  if (period > 1.5 * ts && period <= tl)
    cs = 1.5 * sd1 / (period * r_over_ie);
  else if (period > tl)
    cs = sd1 * tl / (period * period * r_over_ie);
  cs = std::min(cs, upper);
  double lower = std::max(0.044 * sds * d.at("Ie").get<double>(), 0.01);
  if (s1 >= 0.6)
    lower = std::max(lower, 0.5 * s1 / r_over_ie);
  return std::max(cs, lower);
}

class FrameExample : public ::testing::TestWithParam<Example> {
protected:
  void SetUp() override {
    model_file_ = kFrames / GetParam().folder / "model.json";
    ASSERT_TRUE(fs::exists(model_file_)) << model_file_;
    model_ = read_model(model_file_);
    for (const auto& node : model_.at("nodes")) {
      const auto& xyz = node.at("xyz");
      nodes_[node.at("id").get<int>()] = {xyz.at(0).get<double>(), xyz.at(1).get<double>(),
                                          xyz.at(2).get<double>()};
    }
  }

  bool has_node(const json& id) const { return nodes_.count(id.get<int>()) == 1; }
  const Point& node(const json& id) const { return nodes_.at(id.get<int>()); }

  /// The design entries of every brace, by brace name (3D: both directions).
  std::map<std::string, json> brace_designs() const {
    std::map<std::string, json> designs;
    const json& design = model_.at("design");
    std::vector<json> lists;
    if (design.contains("braces"))
      lists.push_back(design.at("braces"));
    if (design.contains("directions"))
      for (const auto& [direction, entry] : design.at("directions").items())
        lists.push_back(entry.at("braces"));
    for (const auto& list : lists)
      for (const auto& brace : list)
        designs[brace.at("name").get<std::string>()] = brace;
    return designs;
  }

  fs::path model_file_;
  json model_;
  std::map<int, Point> nodes_;
};

TEST_P(FrameExample, HasTheSchemaBlocksItsDimensionAndItsStoreys) {
  for (const char* key : {"title", "dimension", "nodes", "supports", "constraints", "masses",
                          "sections", "elements", "gravity", "damping", "analysis", "ground_motion",
                          "stories", "floors", "recorders", "design"})
    EXPECT_TRUE(model_.contains(key)) << key;
  EXPECT_EQ(model_.at("dimension").get<int>(), GetParam().dimension);
  EXPECT_EQ(model_.at("stories").size(), static_cast<std::size_t>(GetParam().storeys));
  EXPECT_EQ(model_.at("floors").size(), static_cast<std::size_t>(GetParam().storeys));
  EXPECT_EQ(model_.at("design").at("story_shears").size(),
            static_cast<std::size_t>(GetParam().storeys));
  EXPECT_EQ(model_.at("damping").at("type"), "rayleigh");
  EXPECT_EQ(model_.at("analysis").at("integrator"), "newmark");
  EXPECT_EQ(model_.at("analysis").at("dt").get<double>(), 0.005);
  EXPECT_EQ(model_.at("recorders").at("braces"), "all");
}

TEST_P(FrameExample, NodeAndElementIdsArePositiveAndUnique) {
  std::set<int> node_ids;
  for (const auto& node : model_.at("nodes")) {
    const int id = node.at("id");
    EXPECT_GT(id, 0);
    EXPECT_TRUE(node_ids.insert(id).second) << "node " << id << " given twice";
    ASSERT_EQ(node.at("xyz").size(), 3u);
    if (GetParam().dimension == 2) {
      EXPECT_EQ(node.at("xyz").at(1).get<double>(), 0.0) << "planar node " << id;
    }
  }
  std::set<int> element_ids;
  for (const auto& element : model_.at("elements")) {
    const int id = element.at("id");
    EXPECT_GT(id, 0);
    EXPECT_TRUE(element_ids.insert(id).second) << "element " << id << " given twice";
  }
}

TEST_P(FrameExample, ElementsReferToExistingNodesSectionsAndBraceFiles) {
  const std::set<std::string> types = {"elastic_beam", "truss", "spring", "fiber_beam", "brb"};
  std::set<int> used;
  for (const auto& element : model_.at("elements")) {
    const int id = element.at("id");
    const std::string type = element.at("type");
    EXPECT_EQ(types.count(type), 1u) << "element " << id << " type " << type;
    const auto& ends = element.at("nodes");
    ASSERT_EQ(ends.size(), 2u) << "element " << id;
    for (const auto& n : ends) {
      EXPECT_TRUE(has_node(n)) << "element " << id << " node " << n;
      used.insert(n.get<int>());
    }
    if (has_node(ends.at(0)) && has_node(ends.at(1))) {
      EXPECT_GT(distance(node(ends.at(0)), node(ends.at(1))), 1.0) << "element " << id;
    }
    if (type == "elastic_beam") {
      EXPECT_TRUE(model_.at("sections").contains(element.at("section").get<std::string>()))
          << "element " << id;
      const std::string geometry = element.at("geometry");
      EXPECT_TRUE(geometry == "linear" || geometry == "pdelta" || geometry == "corotational")
          << "element " << id;
    }
    if (type == "brb") {
      EXPECT_TRUE(fs::exists(model_file_.parent_path() / element.at("brace").get<std::string>()))
          << "element " << id;
      EXPECT_EQ(element.at("fidelity"), "auto");
      EXPECT_EQ(element.at("mode"), "condensed");
    }
  }
  for (const auto& [id, xyz] : nodes_)
    EXPECT_EQ(used.count(id), 1u) << "node " << id << " belongs to no element";
  for (const auto& [name, section] : model_.at("sections").items())
    for (const char* key : {"E", "G", "A", "Iy", "Iz", "J"})
      EXPECT_GT(section.at(key).get<double>(), 0.0) << name << " " << key;
}

TEST_P(FrameExample, SupportsConstraintsStoriesFloorsAndLoadsReferToExistingNodes) {
  for (const auto& support : model_.at("supports")) {
    EXPECT_TRUE(has_node(support.at("node")));
    EXPECT_EQ(node(support.at("node"))[2], 0.0) << "support above the base";
  }
  for (const auto& constraint : model_.at("constraints")) {
    ASSERT_TRUE(has_node(constraint.at("master")));
    const double master_z = node(constraint.at("master"))[2];
    std::vector<json> slaves;
    if (constraint.at("type") == "rigid_diaphragm")
      slaves.assign(constraint.at("nodes").begin(), constraint.at("nodes").end());
    else if (constraint.at("type") == "equal_dof")
      slaves.push_back(constraint.at("slave"));
    else
      ADD_FAILURE() << "constraint type " << constraint.at("type");
    EXPECT_FALSE(slaves.empty());
    for (const auto& slave : slaves) {
      ASSERT_TRUE(has_node(slave)) << slave;
      EXPECT_NE(slave, constraint.at("master"));
      // A floor's constraint ties nodes of that floor.
      EXPECT_EQ(node(slave)[2], master_z) << "slave " << slave;
    }
  }
  double previous_top = 0.0;
  for (const auto& story : model_.at("stories")) {
    ASSERT_TRUE(has_node(story.at("bottom")));
    ASSERT_TRUE(has_node(story.at("top")));
    EXPECT_EQ(node(story.at("bottom"))[2], previous_top) << "stories stack from the base";
    EXPECT_GT(node(story.at("top"))[2], node(story.at("bottom"))[2]);
    previous_top = node(story.at("top"))[2];
  }
  for (const auto& floor : model_.at("floors"))
    EXPECT_TRUE(has_node(floor.at("node")));
  for (const auto& mass : model_.at("masses"))
    EXPECT_TRUE(has_node(mass.at("node")));
  for (const auto& load : model_.at("gravity").at("loads")) {
    EXPECT_TRUE(has_node(load.at("node")));
    EXPECT_EQ(load.at("force").size(), 6u);
  }
}

TEST_P(FrameExample, BraceFilesAreReadAndSpanTheirWorkPointsWithTheDesignedCore) {
  const auto designs = brace_designs();
  int braces = 0;
  for (const auto& element : model_.at("elements")) {
    if (element.at("type") != "brb")
      continue;
    ++braces;
    const int id = element.at("id");
    const fs::path file = model_file_.parent_path() / element.at("brace").get<std::string>();
    ASSERT_TRUE(fs::exists(file)) << "element " << id << ": no brace file " << file;
    const double work_points =
        distance(node(element.at("nodes").at(0)), node(element.at("nodes").at(1)));
    // The brace file's own numbers: connection + transition at both ends + yielding length.
    const json raw = read_model(file);
    const double length = raw.at("core").at("yielding_length").get<double>() +
                          2.0 * raw.at("transition").at("length").get<double>() +
                          2.0 * raw.at("connection").at("length").get<double>();
    EXPECT_NEAR(length, work_points, 1.0) << "element " << id << " " << file;
    // The same brace through the brace reader (every key of the schema checked).
    model::BraceSpec spec;
    ASSERT_NO_THROW(spec = read_brace(file)) << file;
    EXPECT_NEAR(spec.total_length(), work_points, 1e-6) << file;
    ASSERT_TRUE(spec.casing.has_value()) << file;
    // Its model (core, end zones, casing, contact links) builds: the geometry is consistent.
    double yield_force = 0.0;
    ASSERT_NO_THROW({
      const model::BraceModel brace = model::build_brace_model(spec);
      yield_force = brace.yield_force;
    }) << file;
    ASSERT_EQ(designs.count(spec.name), 1u) << "no design entry for " << spec.name;
    const json& design = designs.at(spec.name);
    const double fy = spec.steel.yield_stress;
    const double core_area = spec.core_section.mesh().total_area();
    EXPECT_NEAR(core_area, design.at("Asc").get<double>(), 1e-6 * core_area) << file;
    EXPECT_GE(core_area, design.at("Asc_required").get<double>()) << file;
    EXPECT_GE(0.9 * fy * core_area, design.at("Pu").get<double>()) << file; // phi Fysc Asc >= Pu
    EXPECT_NEAR(yield_force, design.at("Py").get<double>(), 1e-6 * yield_force) << file;
    // End zones stay elastic at the brace's largest compression.
    const double pmax = design.at("Pmax");
    EXPECT_GE(fy * spec.transition->section.mesh().total_area(), pmax) << file;
    EXPECT_GE(fy * spec.connection->section.mesh().total_area(), pmax) << file;
    // Casing: Euler load of the square tube (closed form, steel only, pinned over the
    // work-point length) at least 1.5 times the largest compression.
    const auto& tube = spec.casing->tube;
    ASSERT_EQ(tube.shape, model::SectionShape::rectangular_tube);
    const double inner = tube.width - 2.0 * tube.wall;
    const double inertia = (std::pow(tube.width, 4) - std::pow(inner, 4)) / 12.0;
    const double euler = std::numbers::pi * std::numbers::pi *
                         spec.casing->tube_steel.youngs_modulus * inertia /
                         (work_points * work_points);
    EXPECT_GE(euler, 1.5 * pmax) << file;
    EXPECT_EQ(spec.casing->gap_y, 1.0);
    EXPECT_EQ(spec.casing->friction_coefficient, 0.1);
  }
  EXPECT_EQ(braces, 2 * GetParam().storeys * (GetParam().dimension == 3 ? 4 : 1));
}

TEST_P(FrameExample, MassesArePositiveAndAddUpToTheSeismicWeight) {
  const json& design = model_.at("design");
  double translational = 0.0;
  for (const auto& entry : model_.at("masses")) {
    const json& mass = entry.at("mass");
    if (mass.is_number()) {
      EXPECT_GT(mass.get<double>(), 0.0);
      translational += mass.get<double>();
    } else {
      ASSERT_EQ(mass.size(), 6u);
      for (const auto& m : mass)
        EXPECT_GE(m.get<double>(), 0.0);
      EXPECT_GT(mass.at(0).get<double>(), 0.0);
      EXPECT_EQ(mass.at(0).get<double>(), mass.at(1).get<double>());
      translational += mass.at(0).get<double>();
      // Rigid floor a x b of uniform mass: Izz = m (a^2 + b^2) / 12.
      const double a = design.at("plan").at(0), b = design.at("plan").at(1);
      EXPECT_NEAR(mass.at(5).get<double>(), mass.at(0).get<double>() * (a * a + b * b) / 12.0,
                  1e-9 * mass.at(5).get<double>());
    }
  }
  const double weight = design.at("seismic_weight");
  EXPECT_NEAR(translational, weight / kGravity, 1e-9 * translational);
  // Gravity (1.0 D): the nodal loads carry the same weight, downwards.
  double vertical = 0.0;
  for (const auto& load : model_.at("gravity").at("loads")) {
    EXPECT_LT(load.at("force").at(2).get<double>(), 0.0);
    vertical += load.at("force").at(2).get<double>();
  }
  EXPECT_NEAR(-vertical, weight, 1e-9 * weight);
}

TEST_P(FrameExample, DesignBlockFollowsTheEquivalentLateralForceProcedure) {
  const json& d = model_.at("design");
  const double ss = d.at("site").at("SS"), s1 = d.at("site").at("S1");
  EXPECT_NEAR(d.at("SMS").get<double>(), d.at("Fa").get<double>() * ss, 1e-12);
  EXPECT_NEAR(d.at("SM1").get<double>(), d.at("Fv").get<double>() * s1, 1e-12);
  EXPECT_NEAR(d.at("SDS").get<double>(), 2.0 / 3.0 * d.at("SMS").get<double>(), 1e-12);
  EXPECT_NEAR(d.at("SD1").get<double>(), 2.0 / 3.0 * d.at("SM1").get<double>(), 1e-12);
  // Table 12.2-1 B.26 (BRBF) and the issue's site.
  EXPECT_EQ(d.at("R").get<double>(), 8.0);
  EXPECT_EQ(d.at("Cd").get<double>(), 5.0);
  EXPECT_EQ(d.at("Omega0").get<double>(), 2.5);
  EXPECT_EQ(d.at("Ie").get<double>(), 1.0);
  // Ta = 0.0731 hn^0.75 (hn in m) from the model's own geometry: the roof's height.
  double roof = 0.0;
  for (const auto& [id, xyz] : nodes_)
    roof = std::max(roof, xyz[2]);
  const double ta = 0.0731 * std::pow(roof / 1000.0, 0.75);
  EXPECT_NEAR(d.at("Ta").get<double>(), ta, 1e-12);
  EXPECT_NEAR(d.at("CuTa").get<double>(), 1.4 * ta, 1e-12);
  EXPECT_NEAR(d.at("T").get<double>(), ta, 1e-12);
  const double cs = seismic_response_coefficient(d);
  EXPECT_NEAR(d.at("Cs").get<double>(), cs, 1e-12);
  const double building_v = d.at("building_V");
  EXPECT_NEAR(building_v, cs * d.at("building_seismic_weight").get<double>(), 1e-9 * building_v);
  const double v = d.at("V");
  EXPECT_NEAR(v, d.at("frame_share").get<double>() * building_v, 1e-9 * v);
  // Vertical distribution: the floor forces add up to V, each storey shear is the sum of the
  // forces at and above it, so the first storey carries V.
  const auto forces = d.at("floor_forces").get<std::vector<double>>();
  const auto shears = d.at("story_shears").get<std::vector<double>>();
  ASSERT_EQ(forces.size(), shears.size());
  EXPECT_NEAR(std::accumulate(forces.begin(), forces.end(), 0.0), v, 1e-9 * v);
  EXPECT_NEAR(shears.front(), v, 1e-9 * v);
  for (std::size_t i = 0; i < shears.size(); ++i)
    EXPECT_NEAR(shears[i],
                std::accumulate(forces.begin() + static_cast<std::ptrdiff_t>(i), forces.end(), 0.0),
                1e-9 * v);
  const auto weights = d.at("floor_weights").get<std::vector<double>>();
  EXPECT_NEAR(std::accumulate(weights.begin(), weights.end(), 0.0),
              d.at("seismic_weight").get<double>(), 1e-9 * d.at("seismic_weight").get<double>());
}

INSTANTIATE_TEST_SUITE_P(Frames, FrameExample,
                         ::testing::Values(Example{"brbf3", 2, 3}, Example{"brbf9", 2, 9},
                                           Example{"brbf4_3d", 3, 4}),
                         [](const ::testing::TestParamInfo<Example>& info) {
                           return info.param.folder;
                         });

} // namespace
} // namespace brb::io
