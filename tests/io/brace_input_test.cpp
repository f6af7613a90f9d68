// Brace files: the schema of the README ("Brace files") mapped onto model::BraceSpec, the
// example braces, and every invalid input reported as an InputError naming the file and the
// JSON path.
#include "brb/io/brace_input.hpp"
#include "brb/io/input_error.hpp"
#include "brb/model/brace_model.hpp"
#include "io/scratch_directory.hpp"
#include "support/brace_fixtures.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace brb::io {
namespace {

using model::BendingAxis;
using model::EndCondition;
using model::ImperfectionShape;
using model::SectionShape;
using nlohmann::json;

const std::filesystem::path kExampleBraces =
    std::filesystem::path(BRB_SOURCE_DIR) / "examples" / "braces";

json s275() {
  return {{"E", 210000.0}, {"nu", 0.3}, {"fy", 275.0}, {"H_kin", 21000.0}, {"H_iso", 0.0}};
}

/// The smallest valid brace: a bare rectangular plate core, every optional key left out.
json minimal_brace() {
  return {{"core",
           {{"section", {{"shape", "rectangle"}, {"width", 40.0}, {"depth", 10.0}}},
            {"steel", s275()},
            {"yielding_length", 300.0}}}};
}

/// A brace that gives every key of the schema.
json full_brace() {
  json steel = s275();
  steel["units"] = "MPa";
  steel["chaboche"] = json::array({{{"C", 6000.0}, {"gamma", 60.0}}});
  steel["voce"] = {{"Q", 40.0}, {"b", 10.0}};
  steel["fu"] = 430.0;
  steel["Gf"] = 60.0;
  return {{"name", "test brace"},
          {"units", "mm"},
          {"core",
           {{"section", {{"shape", "circle"}, {"diameter", 22.0}, {"fibers", {3, 12}}}},
            {"steel", steel},
            {"yielding_length", 2000.0},
            {"elements", 10},
            {"integration", {{"rule", "gauss_legendre"}, {"points", 2}}}}},
          {"transition",
           {{"length", 40.0},
            {"section", {{"shape", "circular_tube"}, {"diameter", 60.0}, {"wall", 5.0}}},
            {"elements", 2}}},
          {"connection",
           {{"length", 250.0},
            {"section",
             {{"shape", "cruciform"},
              {"width", 120.0},
              {"depth", 100.0},
              {"thickness", 12.0},
              {"fibers", {6, 2}}}}}},
          {"ends", "fixed"},
          {"imperfection", {{"shape", "buckling_mode"}, {"amplitude", 1.5}, {"direction", "y"}}},
          {"casing", nullptr}};
}

TEST(BraceInput, ReadsEveryKeyIntoTheSpec) {
  const model::BraceSpec spec = parse_brace(full_brace().dump(), "full.json");
  EXPECT_EQ(spec.name, "test brace");

  EXPECT_EQ(spec.core_section.shape, SectionShape::circle);
  EXPECT_EQ(spec.core_section.diameter, 22.0);
  EXPECT_EQ(spec.core_section.fibers_a, 3);
  EXPECT_EQ(spec.core_section.fibers_b, 12);
  EXPECT_EQ(spec.steel.youngs_modulus, 210000.0);
  EXPECT_EQ(spec.steel.poissons_ratio, 0.3);
  EXPECT_EQ(spec.steel.yield_stress, 275.0);
  EXPECT_EQ(spec.steel.kinematic_hardening, 21000.0);
  EXPECT_EQ(spec.steel.isotropic_hardening, 0.0);
  ASSERT_EQ(spec.steel.chaboche.size(), 1u);
  EXPECT_EQ(spec.steel.chaboche[0].modulus, 6000.0);
  EXPECT_EQ(spec.steel.chaboche[0].recall, 60.0);
  EXPECT_EQ(spec.steel.voce_saturation, 40.0);
  EXPECT_EQ(spec.steel.voce_rate, 10.0);
  ASSERT_TRUE(spec.steel.damage.has_value());
  EXPECT_EQ(spec.steel.damage->onset_stress, 430.0);
  EXPECT_EQ(spec.steel.damage->fracture_energy, 60.0);
  EXPECT_EQ(spec.yielding_length, 2000.0);
  EXPECT_EQ(spec.core_elements, 10);
  EXPECT_EQ(spec.integration_rule, element::IntegrationRule::gauss_legendre);
  EXPECT_EQ(spec.integration_points, 2);

  ASSERT_TRUE(spec.transition.has_value());
  EXPECT_EQ(spec.transition->length, 40.0);
  EXPECT_EQ(spec.transition->elements, 2);
  EXPECT_EQ(spec.transition->section.shape, SectionShape::circular_tube);
  EXPECT_EQ(spec.transition->section.diameter, 60.0);
  EXPECT_EQ(spec.transition->section.wall, 5.0);

  ASSERT_TRUE(spec.connection.has_value());
  EXPECT_EQ(spec.connection->length, 250.0);
  EXPECT_EQ(spec.connection->elements, 1); // the default
  EXPECT_EQ(spec.connection->section.shape, SectionShape::cruciform);
  EXPECT_EQ(spec.connection->section.width, 120.0);
  EXPECT_EQ(spec.connection->section.depth, 100.0);
  EXPECT_EQ(spec.connection->section.thickness, 12.0);
  EXPECT_EQ(spec.connection->section.fibers_a, 6);
  EXPECT_EQ(spec.connection->section.fibers_b, 2);

  EXPECT_EQ(spec.ends, EndCondition::fixed);
  EXPECT_EQ(spec.imperfection.shape, ImperfectionShape::buckling_mode);
  EXPECT_EQ(spec.imperfection.amplitude, 1.5);
  EXPECT_EQ(spec.imperfection.direction, BendingAxis::y);
  EXPECT_EQ(spec.total_length(), 2000.0 + 2.0 * 40.0 + 2.0 * 250.0);
}

TEST(BraceInput, LeavesOutOptionalKeysForTheirDefaults) {
  const model::BraceSpec spec = parse_brace(minimal_brace().dump(), "minimal.json");
  EXPECT_EQ(spec.name, "");
  EXPECT_EQ(spec.core_section.shape, SectionShape::rectangle);
  EXPECT_EQ(spec.core_section.width, 40.0);
  EXPECT_EQ(spec.core_section.depth, 10.0);
  EXPECT_EQ(spec.core_elements, 16);
  EXPECT_EQ(spec.integration_rule, element::IntegrationRule::gauss_lobatto);
  EXPECT_FALSE(spec.steel.damage.has_value());
  EXPECT_FALSE(spec.transition.has_value());
  EXPECT_FALSE(spec.connection.has_value());
  EXPECT_EQ(spec.ends, EndCondition::pinned);
  // A bow of L / 1000 about the weak axis: the 10 mm depth is along z.
  EXPECT_EQ(spec.imperfection.shape, ImperfectionShape::bow);
  EXPECT_DOUBLE_EQ(spec.imperfection.amplitude, 300.0 / 1000.0);
  EXPECT_EQ(spec.imperfection.direction, BendingAxis::z);
}

TEST(BraceInput, DefaultImperfectionBowsAboutTheWeakAxis) {
  json brace = minimal_brace();
  brace["core"]["section"]["width"] = 10.0; // now the thin direction is y
  brace["core"]["section"]["depth"] = 40.0;
  brace["imperfection"] = {{"direction", "weak"}};
  const model::BraceSpec spec = parse_brace(brace.dump(), "deep.json");
  EXPECT_EQ(spec.imperfection.direction, BendingAxis::y);
}

TEST(BraceInput, AcceptsNullZonesAndCasingAndComments) {
  const std::string text = "// a bare core\n" + [] {
    json brace = minimal_brace();
    brace["transition"] = nullptr;
    brace["connection"] = nullptr;
    brace["casing"] = nullptr;
    return brace.dump(2);
  }();
  const model::BraceSpec spec = parse_brace(text, "nulls.json");
  EXPECT_FALSE(spec.transition.has_value());
  EXPECT_FALSE(spec.connection.has_value());
}

TEST(BraceInput, ReadsAFileAsItsText) {
  const testing::ScratchDirectory scratch;
  const auto file = scratch.write("brace.json", full_brace().dump());
  const model::BraceSpec from_file = read_brace(file);
  const model::BraceSpec from_text = parse_brace(full_brace().dump(), file.string());
  EXPECT_EQ(from_file.name, from_text.name);
  EXPECT_EQ(from_file.total_length(), from_text.total_length());
  EXPECT_EQ(from_file.core_elements, from_text.core_elements);
}

TEST(BraceInput, MissingFileIsNamed) {
  const testing::ScratchDirectory scratch;
  const auto file = scratch.path() / "absent.json";
  try {
    read_brace(file);
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), file.string());
  }
}

TEST(BraceExamples, GironaD3MatchesTheSharedFixture) {
  const model::BraceSpec read = read_brace(kExampleBraces / "girona_D3_bare.json");
  const model::BraceSpec fixture = test::girona_d3_bare_core();
  EXPECT_EQ(read.name, fixture.name);
  EXPECT_EQ(read.core_section.diameter, fixture.core_section.diameter);
  EXPECT_EQ(read.yielding_length, fixture.yielding_length);
  ASSERT_TRUE(read.connection && read.transition);
  EXPECT_EQ(read.connection->length, fixture.connection->length);
  EXPECT_EQ(read.connection->section.diameter, fixture.connection->section.diameter);
  EXPECT_EQ(read.transition->length, fixture.transition->length);
  EXPECT_EQ(read.transition->section.diameter, fixture.transition->section.diameter);
  EXPECT_EQ(read.total_length(), 2808.0); // L_co of bar D3 (BRB_SOURCE_FACTS section 7)
  EXPECT_EQ(read.steel.yield_stress, fixture.steel.yield_stress);
  EXPECT_EQ(read.steel.kinematic_hardening, fixture.steel.kinematic_hardening);
  EXPECT_EQ(read.ends, fixture.ends);
  EXPECT_DOUBLE_EQ(read.imperfection.amplitude, fixture.imperfection.amplitude);
}

TEST(BraceExamples, EveryExampleBuildsAModelYieldingAtFyTimesTheCoreArea) {
  int examples = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kExampleBraces)) {
    if (entry.path().extension() != ".json")
      continue;
    ++examples;
    SCOPED_TRACE(entry.path().string());
    const model::BraceSpec spec = read_brace(entry.path());
    EXPECT_FALSE(spec.name.empty());
    const model::BraceModel brace = model::build_brace_model(spec);
    const double core_area = spec.core_section.mesh().total_area();
    EXPECT_DOUBLE_EQ(brace.yield_force, spec.steel.yield_stress * core_area);
    // End zones are stiffer than the core: dy is above the core's fy / E L_y and below the
    // value with the whole length at the core's section.
    const double strain = spec.steel.yield_stress / spec.steel.youngs_modulus;
    EXPECT_GT(brace.yield_deformation, strain * spec.yielding_length);
    EXPECT_LT(brace.yield_deformation, strain * spec.total_length());
  }
  EXPECT_GE(examples, 2);
}

// ---- Rejected inputs ----

struct BadBrace {
  std::string name;
  std::function<void(json&)> spoil; ///< turns full_brace() into the bad input
  std::string path;                 ///< the JSON path the message must name
};

void PrintTo(const BadBrace& bad, std::ostream* out) {
  *out << bad.name;
}

class BraceRejected : public ::testing::TestWithParam<BadBrace> {};

TEST_P(BraceRejected, InputErrorNamesTheFileAndTheJsonPath) {
  const BadBrace& bad = GetParam();
  json brace = full_brace();
  bad.spoil(brace);
  const testing::ScratchDirectory scratch;
  const auto file = scratch.write("bad brace.json", brace.dump());
  try {
    read_brace(file);
    FAIL() << "no InputError for " << brace.dump();
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), file.string());
    EXPECT_EQ(error.location(), bad.path) << error.what();
    EXPECT_EQ(std::string(error.what()).rfind(file.string() + ": " + bad.path + ": ", 0), 0u)
        << error.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    BraceInputErrors, BraceRejected,
    ::testing::Values(
        BadBrace{"negative_yielding_length",
                 [](json& brace) { brace["core"]["yielding_length"] = -2000.0; },
                 "/core/yielding_length"},
        BadBrace{"zero_diameter", [](json& brace) { brace["core"]["section"]["diameter"] = 0.0; },
                 "/core/section/diameter"},
        BadBrace{"negative_plate_depth",
                 [](json& brace) {
                   brace["core"]["section"] = {
                       {"shape", "rectangle"}, {"width", 40.0}, {"depth", -10.0}};
                 },
                 "/core/section/depth"},
        BadBrace{"tube_wall_thicker_than_radius",
                 [](json& brace) { brace["transition"]["section"]["wall"] = 30.0; },
                 "/transition/section/wall"},
        BadBrace{"negative_zone_length", [](json& brace) { brace["connection"]["length"] = -1.0; },
                 "/connection/length"},
        BadBrace{"imperfection_longer_than_brace",
                 [](json& brace) { brace["imperfection"]["amplitude"] = 5000.0; },
                 "/imperfection/amplitude"},
        BadBrace{"negative_imperfection",
                 [](json& brace) { brace["imperfection"]["amplitude"] = -1.0; },
                 "/imperfection/amplitude"},
        BadBrace{"unknown_top_level_key", [](json& brace) { brace["cassing"] = nullptr; },
                 "/cassing"},
        BadBrace{"unknown_core_key", [](json& brace) { brace["core"]["length"] = 2000.0; },
                 "/core/length"},
        BadBrace{"unknown_section_key",
                 [](json& brace) { brace["core"]["section"]["radius"] = 11.0; },
                 "/core/section/radius"},
        BadBrace{"lc_in_brace_steel", [](json& brace) { brace["core"]["steel"]["lc"] = 10.0; },
                 "/core/steel/lc"},
        BadBrace{"missing_core", [](json& brace) { brace.erase("core"); }, "/core"},
        BadBrace{"missing_yielding_length",
                 [](json& brace) { brace["core"].erase("yielding_length"); },
                 "/core/yielding_length"},
        BadBrace{"unknown_shape", [](json& brace) { brace["core"]["section"]["shape"] = "oval"; },
                 "/core/section/shape"},
        BadBrace{"dimension_of_another_shape",
                 [](json& brace) { brace["core"]["section"]["width"] = 22.0; },
                 "/core/section/width"},
        BadBrace{"zero_fibers",
                 [](json& brace) {
                   brace["core"]["section"]["fibers"] = {0, 12};
                 },
                 "/core/section/fibers/0"},
        BadBrace{"fractional_fibers",
                 [](json& brace) {
                   brace["core"]["section"]["fibers"] = {3, 12.5};
                 },
                 "/core/section/fibers/1"},
        BadBrace{"three_fiber_counts",
                 [](json& brace) {
                   brace["core"]["section"]["fibers"] = {3, 12, 2};
                 },
                 "/core/section/fibers"},
        BadBrace{"casing_not_null", [](json& brace) { brace["casing"] = json::object(); },
                 "/casing"},
        BadBrace{"negative_fy", [](json& brace) { brace["core"]["steel"]["fy"] = -275.0; },
                 "/core/steel/fy"},
        BadBrace{"steel_without_E", [](json& brace) { brace["core"]["steel"].erase("E"); },
                 "/core/steel/E"},
        BadBrace{"fu_below_fy", [](json& brace) { brace["core"]["steel"]["fu"] = 200.0; },
                 "/core/steel/fu"},
        BadBrace{"inches", [](json& brace) { brace["units"] = "in"; }, "/units"},
        BadBrace{"unknown_end_condition", [](json& brace) { brace["ends"] = "hinged"; }, "/ends"},
        BadBrace{"too_many_integration_points",
                 [](json& brace) { brace["core"]["integration"]["points"] = 9; },
                 "/core/integration/points"},
        BadBrace{"unknown_integration_rule",
                 [](json& brace) { brace["core"]["integration"]["rule"] = "simpson"; },
                 "/core/integration/rule"},
        BadBrace{"unknown_imperfection_direction",
                 [](json& brace) { brace["imperfection"]["direction"] = "x"; },
                 "/imperfection/direction"},
        BadBrace{"elements_not_a_number", [](json& brace) { brace["core"]["elements"] = "16"; },
                 "/core/elements"}),
    [](const ::testing::TestParamInfo<BadBrace>& info) { return info.param.name; });

// A fiber count the reader accepts (a whole number >= 1) but the mesher does not (a circle
// needs 3 sectors) must be reported at its place in the file, "/core/section/fibers/1".
TEST(BraceInput, FiberCountTheMesherRejectsIsReportedAtItsJsonPath) {
  json brace = full_brace();
  brace["core"]["section"]["fibers"] = {3, 2};
  try {
    parse_brace(brace.dump(), "sectors.json");
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "/core/section/fibers/1") << error.what();
  }
}

} // namespace
} // namespace brb::io
