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

/// The casing of the Girona D3 restrained tests around full_brace()'s 22 mm round core, every
/// key given.
json girona_casing() {
  json tube_steel = s275();
  tube_steel["H_kin"] = 2100.0;
  return {{"tube",
           {{"shape", "circular_tube"}, {"diameter", 115.0}, {"wall", 3.0}, {"fibers", {1, 16}}}},
          {"tube_steel", tube_steel},
          {"mortar", {{"E", 17520.0}, {"nu", 0.2}, {"fc", 50.0}, {"ft", 5.0}, {"Gf", 0.1}}},
          {"gap", {{"y", 0.5}, {"z", 0.5}}},
          {"friction", 0.2},
          {"layer_stiffness", 0.05},
          {"fill_fibers", {2, 12}},
          {"stopper", {{"position", 0.25}}},
          {"core_expansion", 0.3},
          {"high_mode_waves", {{"crest_factor", 3.5}}}};
}

/// full_brace() with girona_casing().
json cased_brace() {
  json brace = full_brace();
  brace["casing"] = girona_casing();
  return brace;
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

TEST(BraceInput, ReadsTheCasingIntoTheSpec) {
  const model::BraceSpec spec = parse_brace(cased_brace().dump(), "cased.json");
  ASSERT_TRUE(spec.casing.has_value());
  const model::CasingSpec& casing = *spec.casing;
  EXPECT_EQ(casing.tube.shape, SectionShape::circular_tube);
  EXPECT_EQ(casing.tube.diameter, 115.0);
  EXPECT_EQ(casing.tube.wall, 3.0);
  EXPECT_EQ(casing.tube.fibers_a, 1);
  EXPECT_EQ(casing.tube.fibers_b, 16);
  EXPECT_EQ(casing.tube_steel.youngs_modulus, 210000.0);
  EXPECT_EQ(casing.tube_steel.yield_stress, 275.0);
  EXPECT_EQ(casing.tube_steel.kinematic_hardening, 2100.0);
  EXPECT_FALSE(casing.tube_steel.damage.has_value());
  EXPECT_EQ(casing.mortar.youngs_modulus, 17520.0);
  EXPECT_EQ(casing.mortar.poissons_ratio, 0.2);
  EXPECT_EQ(casing.mortar.compressive_strength, 50.0);
  EXPECT_EQ(casing.mortar.tensile_strength, 5.0);
  EXPECT_EQ(casing.mortar.fracture_energy, 0.1);
  EXPECT_EQ(casing.gap_y, 0.5);
  EXPECT_EQ(casing.gap_z, 0.5);
  EXPECT_EQ(casing.friction_coefficient, 0.2);
  ASSERT_TRUE(casing.layer_stiffness.has_value());
  EXPECT_EQ(*casing.layer_stiffness, 0.05);
  EXPECT_EQ(casing.fill_fibers_a, 2);
  EXPECT_EQ(casing.fill_fibers_b, 12);
  EXPECT_EQ(casing.stopper_position, 0.25);
  EXPECT_EQ(casing.core_expansion, 0.3);
  ASSERT_TRUE(casing.high_mode_waves.has_value());
  EXPECT_EQ(*casing.high_mode_waves, 3.5);
  // (109 - 22) / 2 - 0.5 = 43 mm of mortar all around
  const auto [thickness_y, thickness_z] = casing.mortar_thickness(spec.core_section);
  EXPECT_DOUBLE_EQ(thickness_y, 43.0);
  EXPECT_DOUBLE_EQ(thickness_z, 43.0);
}

TEST(BraceInput, CasingDefaultsAndOneGapForBothDirections) {
  json brace = full_brace();
  brace["casing"] = girona_casing();
  for (const char* key : {"friction", "layer_stiffness", "fill_fibers", "stopper", "core_expansion",
                          "high_mode_waves"})
    brace["casing"].erase(key);
  brace["casing"]["gap"] = 1.5;
  const model::BraceSpec spec = parse_brace(brace.dump(), "defaults.json");
  ASSERT_TRUE(spec.casing.has_value());
  const model::CasingSpec defaults;
  EXPECT_EQ(spec.casing->gap_y, 1.5);
  EXPECT_EQ(spec.casing->gap_z, 1.5);
  EXPECT_EQ(spec.casing->friction_coefficient, 0.1);
  EXPECT_FALSE(spec.casing->layer_stiffness.has_value());
  EXPECT_EQ(spec.casing->fill_fibers_a, defaults.fill_fibers_a);
  EXPECT_EQ(spec.casing->fill_fibers_b, defaults.fill_fibers_b);
  EXPECT_EQ(spec.casing->stopper_position, 0.5);
  EXPECT_EQ(spec.casing->core_expansion, 0.0); // off by default (brace_spec.hpp says why)
  EXPECT_FALSE(spec.casing->high_mode_waves.has_value()); // off by default
  // true: on at the crest factor 4 of the half-wave's equilibrium; an empty object too
  brace["casing"]["high_mode_waves"] = true;
  EXPECT_EQ(parse_brace(brace.dump(), "waves.json").casing->high_mode_waves, 4.0);
  brace["casing"]["high_mode_waves"] = json::object();
  EXPECT_EQ(parse_brace(brace.dump(), "waves.json").casing->high_mode_waves, 4.0);
  brace["casing"]["high_mode_waves"] = false;
  EXPECT_FALSE(parse_brace(brace.dump(), "waves.json").casing->high_mode_waves.has_value());
}

TEST(BraceInput, RectangularTubeAroundAPlateTakesAGapPerDirection) {
  json brace = minimal_brace(); // 40 x 10 mm plate
  brace["casing"] = girona_casing();
  brace["casing"]["tube"] = {
      {"shape", "rectangular_tube"}, {"width", 80.0}, {"depth", 60.0}, {"wall", 4.0}};
  brace["casing"]["gap"] = {{"y", 1.0}, {"z", 2.0}};
  const model::BraceSpec spec = parse_brace(brace.dump(), "plate.json");
  ASSERT_TRUE(spec.casing.has_value());
  EXPECT_EQ(spec.casing->tube.shape, SectionShape::rectangular_tube);
  EXPECT_EQ(spec.casing->gap_y, 1.0);
  EXPECT_EQ(spec.casing->gap_z, 2.0);
  // y: (72 - 40) / 2 - 1 = 15 mm; z: (52 - 10) / 2 - 2 = 19 mm
  const auto [thickness_y, thickness_z] = spec.casing->mortar_thickness(spec.core_section);
  EXPECT_DOUBLE_EQ(thickness_y, 15.0);
  EXPECT_DOUBLE_EQ(thickness_z, 19.0);
}

TEST(BraceInput, StopperGoesToTheStationNearestItsPosition) {
  json brace = minimal_brace();
  brace["core"]["elements"] = 8; // 9 casing stations
  brace["casing"] = girona_casing();
  brace["casing"]["tube"] = {
      {"shape", "rectangular_tube"}, {"width", 80.0}, {"depth", 60.0}, {"wall", 4.0}};
  for (const auto& [position, station] :
       {std::pair{0.0, 0u}, std::pair{0.25, 2u}, std::pair{0.5, 4u}, std::pair{1.0, 8u}}) {
    brace["casing"]["stopper"]["position"] = position;
    const model::BraceModel built = model::build_brace_model(parse_brace(brace.dump(), "s.json"));
    ASSERT_TRUE(built.casing.has_value());
    EXPECT_EQ(built.casing->stopper_station, station) << "position " << position;
  }
}

/// A 40 x 10 mm plate core (8 elements of 37.5 mm) with 60 mm transitions (2 elements) of a
/// 50 x 10 mm plate and a mortar-filled 80 x 60 x 4 tube, gaps 1 mm.
json plate_brace_with_transition() {
  json brace = minimal_brace();
  brace["core"]["elements"] = 8;
  brace["transition"] = {{"length", 60.0},
                         {"section", {{"shape", "rectangle"}, {"width", 50.0}, {"depth", 10.0}}},
                         {"elements", 2}};
  brace["casing"] = girona_casing();
  brace["casing"]["tube"] = {
      {"shape", "rectangular_tube"}, {"width", 80.0}, {"depth", 60.0}, {"wall", 4.0}};
  brace["casing"]["gap"] = 1.0;
  return brace;
}

TEST(BraceInput, CasingOverlapPutsTheTransitionInsideTheCasing) {
  json brace = plate_brace_with_transition();
  const model::BraceModel without = model::build_brace_model(parse_brace(brace.dump(), "o.json"));
  ASSERT_TRUE(without.casing.has_value());
  EXPECT_EQ(without.casing->nodes.size(), 9u); // the yielding zone's stations only

  brace["casing"]["overlap"] = 40.0; // about one core element (37.5 mm) per end
  const model::BraceSpec spec = parse_brace(brace.dump(), "o.json");
  ASSERT_TRUE(spec.casing.has_value());
  EXPECT_EQ(spec.casing->overlap, 40.0);
  const model::BraceModel with = model::build_brace_model(spec);
  ASSERT_TRUE(with.casing.has_value());
  const model::CasingModel& casing = *with.casing;
  // 9 core stations + 1 overlap station per end (round(40 / 37.5) = 1 element each); the
  // transition's rest keeps its 2 elements: 2 x (1 + 2) + 8 elements in all
  ASSERT_EQ(casing.nodes.size(), 11u);
  EXPECT_EQ(with.beams.size(), 14u);
  EXPECT_NEAR(with.model.coordinates(with.end_node).x(), 300.0 + 2.0 * 60.0, 1e-9);
  // the casing now starts 40 mm before the yielding zone and ends 40 mm after it
  const double first = with.model.coordinates(casing.nodes.front()).x();
  const double last = with.model.coordinates(casing.nodes.back()).x();
  EXPECT_NEAR(last - first, 300.0 + 2.0 * 40.0, 1e-9);
  EXPECT_NEAR(with.model.coordinates(casing.core_nodes.front()).x(), first, 1e-9);
  // an overlap station bears on the 50 mm wide transition over half its 40 mm element: the
  // y face over 20 x 10 mm^2 with (72 - 50) / 2 - 1 = 10 mm of mortar; a core station at
  // mid-length over 37.5 x 10 mm^2 with (72 - 40) / 2 - 1 = 15 mm
  // (the faces' areas: bearing_area_y = tributary x extent_z, bearing_area_z = x extent_y)
  // (checked through the link parameters of the mid station and the tributary lengths)
  EXPECT_NEAR(casing.tributary_length.front(), 20.0, 1e-9);
  EXPECT_NEAR(casing.tributary_length[1], 0.5 * (40.0 + 37.5), 1e-9);
  EXPECT_NEAR(casing.interior_link.bearing_depth_y, 15.0, 1e-12);
  EXPECT_NEAR(casing.interior_link.bearing_area_z, 37.5 * 40.0, 1e-9);
  // the end casing element's fill is cast around the transition: 72 x 52 - 52 x 12 mm^2
  const auto& end_section = casing.beams.front()->local_beam().sections().front();
  EXPECT_NEAR(end_section.second().layout().total_area(), 72.0 * 52.0 - 52.0 * 12.0, 1e-9);
  const auto& core_section = casing.beams[1]->local_beam().sections().front();
  EXPECT_NEAR(core_section.second().layout().total_area(), 72.0 * 52.0 - 42.0 * 12.0, 1e-9);
}

TEST(BraceInput, CasingOverlapIsCheckedAgainstTheTransition) {
  const auto expect_rejected = [](const json& brace, const std::string& location,
                                  const std::string& words) {
    try {
      parse_brace(brace.dump(), "overlap.json");
      ADD_FAILURE() << "no InputError for " << location << " (" << words << ")";
    } catch (const InputError& error) {
      EXPECT_EQ(error.location(), location) << error.what();
      EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
    }
  };
  json longer = plate_brace_with_transition();
  longer["casing"]["overlap"] = 61.0;
  expect_rejected(longer, "/casing/overlap", "at most the transition length 60 mm");
  json negative = plate_brace_with_transition();
  negative["casing"]["overlap"] = -1.0;
  expect_rejected(negative, "/casing/overlap", "must be >= 0");
  json no_transition = plate_brace_with_transition();
  no_transition.erase("transition");
  no_transition["casing"]["overlap"] = 10.0;
  expect_rejected(no_transition, "/casing/overlap", "needs a \"transition\"");
  json wide = plate_brace_with_transition();
  wide["transition"]["section"]["width"] = 71.0; // 71 + 2 x 1 > 72 mm inside
  wide["casing"]["overlap"] = 30.0;
  expect_rejected(wide, "/casing/overlap", "does not fit inside the casing: along y");
  json full = plate_brace_with_transition(); // the whole transition inside: accepted
  full["casing"]["overlap"] = 60.0;
  EXPECT_EQ(parse_brace(full.dump(), "overlap.json").casing->overlap, 60.0);
}

TEST(BraceInput, CasingTooThinSaysByHowMuch) {
  json brace = cased_brace();
  brace["casing"]["tube"]["diameter"] = 24.0; // inside 18 mm < 22 + 2 x 0.5
  try {
    parse_brace(brace.dump(), "thin.json");
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "/casing/tube") << error.what();
    EXPECT_NE(std::string(error.what()).find("short by 5 mm"), std::string::npos) << error.what();
  }
}

TEST(BraceInput, MortarOnlyCasingTakesAnOutline) {
  // The thesis's small BRB (BRB_SOURCE_FACTS section 6): a 10 x 10 mm core in a 30 x 30 mm
  // mortar casing, no steel tube.
  json brace = minimal_brace();
  brace["core"]["section"] = {{"shape", "rectangle"}, {"width", 10.0}, {"depth", 10.0}};
  brace["casing"] = girona_casing();
  brace["casing"].erase("tube");
  brace["casing"].erase("tube_steel");
  brace["casing"]["gap"] = 0.05;
  brace["casing"]["outline"] = {{"shape", "rectangle"}, {"width", 30.0}, {"depth", 30.0}};
  const model::BraceSpec spec = parse_brace(brace.dump(), "small.json");
  ASSERT_TRUE(spec.casing.has_value());
  EXPECT_FALSE(spec.casing->steel_tube);
  EXPECT_EQ(spec.casing->tube.shape, SectionShape::rectangular_tube);
  EXPECT_EQ(spec.casing->tube.wall, 0.0);
  // (30 - 10) / 2 - 0.05 = 9.95 mm of mortar per side
  const auto [thickness_y, thickness_z] = spec.casing->mortar_thickness(spec.core_section);
  EXPECT_DOUBLE_EQ(thickness_y, 9.95);
  EXPECT_DOUBLE_EQ(thickness_z, 9.95);
  // The casing beams carry the mortar only: no steel fibers, and the fill is the outline
  // minus the core's opening, 30^2 - 10.1^2 mm^2.
  const model::BraceModel built = model::build_brace_model(spec);
  ASSERT_TRUE(built.casing.has_value());
  const auto& section = built.casing->beams.front()->local_beam().sections().front();
  EXPECT_EQ(section.first().layout().size(), 0u);
  EXPECT_NEAR(section.second().layout().total_area(), 900.0 - 10.1 * 10.1, 1e-9);
  // Rigid across by default; "splitting": true (element::CasingSplitting) gives each link
  // the walls beside the opening, (30 - 10 - 2 x 0.05) mm x the tributary length, stretched
  // over the outline's 30 mm. A tube casing never splits.
  EXPECT_FALSE(spec.casing->splitting);
  EXPECT_FALSE(built.casing->interior_link.splitting.has_value());
  json split = brace;
  split["casing"]["splitting"] = true;
  const model::BraceModel split_model =
      model::build_brace_model(parse_brace(split.dump(), "small.json"));
  const auto& interior = split_model.casing->interior_link;
  ASSERT_TRUE(interior.splitting.has_value());
  const double tributary =
      split_model.casing->tributary_length[split_model.casing->tributary_length.size() / 2];
  EXPECT_NEAR(interior.splitting->wall_area_y, 19.9 * tributary, 1e-9);
  EXPECT_NEAR(interior.splitting->wall_area_z, 19.9 * tributary, 1e-9);
  EXPECT_EQ(interior.splitting->wall_length_y, 30.0);
  EXPECT_EQ(interior.splitting->wall_length_z, 30.0);
}

TEST(BraceInput, MortarOnlyCasingRejectsTubeSteelAndOtherShapes) {
  json base = minimal_brace();
  base["core"]["section"] = {{"shape", "rectangle"}, {"width", 10.0}, {"depth", 10.0}};
  base["casing"] = girona_casing();
  base["casing"].erase("tube");
  base["casing"].erase("tube_steel");
  base["casing"]["gap"] = 0.05;
  base["casing"]["outline"] = {{"shape", "rectangle"}, {"width", 30.0}, {"depth", 30.0}};
  const auto expect_rejected = [](const json& brace, const std::string& location,
                                  const std::string& words) {
    try {
      parse_brace(brace.dump(), "small.json");
      ADD_FAILURE() << "no InputError for " << location;
    } catch (const InputError& error) {
      EXPECT_EQ(error.location(), location) << error.what();
      EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
    }
  };
  json with_steel = base;
  with_steel["casing"]["tube_steel"] = s275();
  expect_rejected(with_steel, "/casing/tube_steel", "no tube steel");
  json both = base;
  both["casing"]["tube"] = girona_casing()["tube"];
  expect_rejected(both, "/casing/outline", "not both");
  json cruciform = base;
  cruciform["casing"]["outline"] = {
      {"shape", "cruciform"}, {"width", 30.0}, {"depth", 30.0}, {"thickness", 5.0}};
  expect_rejected(cruciform, "/casing/outline/shape", "rectangle or a circle");
  json thin = base;
  thin["casing"]["outline"]["width"] = 10.05; // no room for 10 mm + 2 x 0.05 mm
  expect_rejected(thin, "/casing/outline", "casing too thin");
  json word = base;
  word["casing"]["splitting"] = "yes";
  expect_rejected(word, "/casing/splitting", "true or false");
  json tube = base;
  tube["casing"].erase("outline");
  tube["casing"]["tube"] = {
      {"shape", "rectangular_tube"}, {"width", 40.0}, {"depth", 40.0}, {"wall", 3.0}};
  tube["casing"]["tube_steel"] = s275();
  tube["casing"]["splitting"] = true;
  expect_rejected(tube, "/casing/splitting", "a steel tube holds the split");
  tube["casing"]["splitting"] = false; // allowed: the tube casing does not split anyway
  EXPECT_FALSE(parse_brace(tube.dump(), "tube.json").casing->splitting);
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

TEST(BraceExamples, GironaD3RestrainedIsTheBareCoreInTheSlowTestsCasing) {
  const model::BraceSpec read = read_brace(kExampleBraces / "girona_D3_restrained.json");
  const model::BraceSpec core = test::girona_d3_bare_core(16, false);
  EXPECT_EQ(read.core_section.diameter, core.core_section.diameter);
  EXPECT_EQ(read.yielding_length, core.yielding_length);
  EXPECT_EQ(read.total_length(), core.total_length()); // no end zones
  EXPECT_EQ(read.steel.kinematic_hardening, core.steel.kinematic_hardening);
  EXPECT_DOUBLE_EQ(read.imperfection.amplitude, core.imperfection.amplitude);
  ASSERT_TRUE(read.casing.has_value());
  const model::CasingSpec& casing = *read.casing;
  EXPECT_EQ(casing.tube.shape, SectionShape::circular_tube);
  EXPECT_EQ(casing.tube.diameter, 115.0);
  EXPECT_EQ(casing.tube.wall, 3.0);
  EXPECT_EQ(casing.tube_steel.kinematic_hardening, 2100.0);
  EXPECT_EQ(casing.mortar.youngs_modulus, 17520.0);
  EXPECT_EQ(casing.mortar.fracture_energy, 0.1);
  EXPECT_EQ(casing.gap_y, 0.5);
  EXPECT_EQ(casing.gap_z, 0.5);
  EXPECT_EQ(casing.friction_coefficient, 0.1);
  EXPECT_EQ(casing.fill_fibers_a, 2);
  EXPECT_EQ(casing.fill_fibers_b, 16);
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
    // value with the whole length at the core's section; without them it is fy / E L_y.
    const double strain = spec.steel.yield_stress / spec.steel.youngs_modulus;
    if (spec.transition || spec.connection) {
      EXPECT_GT(brace.yield_deformation, strain * spec.yielding_length);
      EXPECT_LT(brace.yield_deformation, strain * spec.total_length());
    } else {
      EXPECT_DOUBLE_EQ(brace.yield_deformation, strain * spec.yielding_length);
    }
  }
  EXPECT_GE(examples, 2);
}

TEST(BraceInput, ElementBlockChoosesFidelityAndModeWithFullCondensedByDefault) {
  const model::BraceSpec defaults = parse_brace(minimal_brace().dump(), "b.json");
  EXPECT_EQ(defaults.element.fidelity, model::Fidelity::full);
  EXPECT_EQ(defaults.element.mode, model::ElementMode::condensed);
  json brace = minimal_brace();
  brace["element"] = {{"fidelity", "truss"}, {"mode", "expanded"}};
  const model::BraceSpec spec = parse_brace(brace.dump(), "b.json");
  EXPECT_EQ(spec.element.fidelity, model::Fidelity::truss);
  EXPECT_EQ(spec.element.mode, model::ElementMode::expanded);
}

TEST(BraceInput, AutoFidelityIsRejectedWithTheChoicesThereAre) {
  json brace = minimal_brace();
  brace["element"] = {{"fidelity", "auto"}};
  try {
    parse_brace(brace.dump(), "b.json");
    FAIL() << "auto accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("\"auto\" is not available yet"), std::string::npos) << message;
    EXPECT_NE(message.find("\"truss\""), std::string::npos) << message;
  }
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
        BadBrace{"element_fidelity_auto_not_yet",
                 [](json& brace) { brace["element"] = {{"fidelity", "auto"}}; },
                 "/element/fidelity"},
        BadBrace{"element_fidelity_unknown",
                 [](json& brace) { brace["element"] = {{"fidelity", "shell"}}; },
                 "/element/fidelity"},
        BadBrace{"element_mode_unknown",
                 [](json& brace) { brace["element"] = {{"mode", "lumped"}}; }, "/element/mode"},
        BadBrace{"element_unknown_key",
                 [](json& brace) { brace["element"] = {{"fidelity", "full"}, {"order", 2}}; },
                 "/element/order"},
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
        BadBrace{"unknown_casing_key",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["tube_wall"] = 3.0;
                 },
                 "/casing/tube_wall"},
        BadBrace{"casing_not_an_object",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"] = 115.0;
                 },
                 "/casing"},
        BadBrace{"casing_without_tube",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"].erase("tube");
                 },
                 "/casing/tube"},
        BadBrace{"casing_tube_not_a_tube",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["tube"] = {{"shape", "circle"}, {"diameter", 115.0}};
                 },
                 "/casing/tube/shape"},
        BadBrace{
            "circular_tube_around_a_plate",
            [](json& brace) {
              brace["casing"] = girona_casing();
              brace["core"]["section"] = {{"shape", "rectangle"}, {"width", 40.0}, {"depth", 10.0}};
            },
            "/casing/tube/shape"},
        BadBrace{"casing_without_tube_steel",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"].erase("tube_steel");
                 },
                 "/casing/tube_steel"},
        BadBrace{"casing_tube_steel_lc",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["tube_steel"]["lc"] = 10.0;
                 },
                 "/casing/tube_steel/lc"},
        BadBrace{"casing_without_mortar",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"].erase("mortar");
                 },
                 "/casing/mortar"},
        BadBrace{"mortar_without_Gf",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["mortar"].erase("Gf");
                 },
                 "/casing/mortar/Gf"},
        BadBrace{"mortar_negative_E",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["mortar"]["E"] = -17520.0;
                 },
                 "/casing/mortar/E"},
        BadBrace{"mortar_ft_above_fc",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["mortar"]["ft"] = 60.0;
                 },
                 "/casing/mortar/fc"},
        BadBrace{"mortar_lc",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["mortar"]["lc"] = 10.0;
                 },
                 "/casing/mortar/lc"},
        BadBrace{"casing_without_gap",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"].erase("gap");
                 },
                 "/casing/gap"},
        BadBrace{"negative_gap_y",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["gap"]["y"] = -0.5;
                 },
                 "/casing/gap/y"},
        BadBrace{"negative_gap",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["gap"] = -0.5;
                 },
                 "/casing/gap"},
        BadBrace{"unequal_gaps_in_circular_tube",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["gap"]["z"] = 1.0;
                 },
                 "/casing/gap"},
        BadBrace{"negative_friction",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["friction"] = -0.1;
                 },
                 "/casing/friction"},
        BadBrace{"zero_layer_stiffness",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["layer_stiffness"] = 0.0;
                 },
                 "/casing/layer_stiffness"},
        BadBrace{"fill_fibers_not_whole",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["fill_fibers"] = {2, 1.5};
                 },
                 "/casing/fill_fibers/1"},
        BadBrace{"fill_with_two_sectors",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["fill_fibers"] = {2, 2};
                 },
                 "/casing/fill_fibers/1"},
        BadBrace{"casing_too_thin",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["tube"]["diameter"] = 24.0;
                 },
                 "/casing/tube"},
        BadBrace{"no_room_for_mortar",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["tube"]["diameter"] = 25.0; // inside 23 = 22 + 2 x 0.5
                 },
                 "/casing/tube"},
        BadBrace{"stopper_outside_the_casing",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["stopper"]["position"] = 1.5;
                 },
                 "/casing/stopper/position"},
        BadBrace{"core_expansion_above_incompressible",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["core_expansion"] = 0.6;
                 },
                 "/casing/core_expansion"},
        BadBrace{"negative_core_expansion",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["core_expansion"] = -0.1;
                 },
                 "/casing/core_expansion"},
        BadBrace{"zero_wave_crest_factor",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["high_mode_waves"]["crest_factor"] = 0.0;
                 },
                 "/casing/high_mode_waves/crest_factor"},
        BadBrace{"unknown_wave_key",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["high_mode_waves"]["wavelength"] = 50.0;
                 },
                 "/casing/high_mode_waves/wavelength"},
        BadBrace{"unknown_stopper_key",
                 [](json& brace) {
                   brace["casing"] = girona_casing();
                   brace["casing"]["stopper"]["station"] = 4;
                 },
                 "/casing/stopper/station"},
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
