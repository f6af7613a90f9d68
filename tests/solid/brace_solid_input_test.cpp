// The brace file's "solid" block: its fields into model::SolidMeshSpec, and each bad mesh
// input reported as an InputError naming the file, the JSON path and what was expected.
#include "brb/io/brace_input.hpp"
#include "brb/io/input_error.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace brb::io {
namespace {

using nlohmann::json;

/// A plate core 40 x 10 mm in a 100 x 60 x 4 mm tube with 1 mm gaps, and a solid block.
json cased_brace(const json& solid) {
  const json steel = {
      {"E", 210000.0}, {"nu", 0.3}, {"fy", 355.0}, {"H_kin", 2100.0}, {"H_iso", 0.0}};
  return {
      {"core",
       {{"section", {{"shape", "rectangle"}, {"width", 40.0}, {"depth", 10.0}}},
        {"steel", steel},
        {"yielding_length", 600.0}}},
      {"imperfection", {{"amplitude", 0.6}}},
      {"casing",
       {{"tube", {{"shape", "rectangular_tube"}, {"width", 100.0}, {"depth", 60.0}, {"wall", 4.0}}},
        {"tube_steel", steel},
        {"mortar", {{"E", 17520.0}, {"nu", 0.2}, {"fc", 50.0}, {"ft", 5.0}, {"Gf", 0.1}}},
        {"gap", 1.0}}},
      {"solid", solid}};
}

/// The location of the InputError that parsing `brace` raises ("none" when it parses).
std::string error_location(const json& brace, std::string* message = nullptr) {
  try {
    (void)parse_brace(brace.dump(), "brace.json");
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "brace.json");
    if (message)
      *message = error.expected();
    return error.location();
  }
  return "none";
}

TEST(BraceSolidInput, ReadsTheSolidBlock) {
  const model::BraceSpec spec = parse_brace(cased_brace({{"elements_across_core", 3},
                                                         {"axial_element_size", 12.5},
                                                         {"elements_through_mortar", 4},
                                                         {"half_length", true},
                                                         {"tube", "homogenised"},
                                                         {"end_faces", "clamped"},
                                                         {"steel_density", 7.8e-9},
                                                         {"mortar_density", 2.4e-9},
                                                         {"mass_scaling", 4.0},
                                                         {"threads", 2},
                                                         {"hourglass", "tangent"},
                                                         {"hourglass_min_scale", 0.1}})
                                                .dump(),
                                            "brace.json");
  ASSERT_TRUE(spec.solid.has_value());
  EXPECT_EQ(spec.solid->elements_across_core, 3);
  EXPECT_EQ(spec.solid->axial_element_size, 12.5);
  EXPECT_EQ(spec.solid->elements_through_mortar, 4);
  EXPECT_TRUE(spec.solid->half_length);
  EXPECT_EQ(spec.solid->tube, model::SolidTube::homogenised);
  EXPECT_EQ(spec.solid->end_faces, model::SolidEndFaces::clamped);
  EXPECT_EQ(spec.solid->steel_density, 7.8e-9);
  EXPECT_EQ(spec.solid->mortar_density, 2.4e-9);
  EXPECT_EQ(spec.solid->mass_scaling, 4.0);
  EXPECT_EQ(spec.solid->threads, 2);
  EXPECT_EQ(spec.solid->hourglass, model::SolidHourglass::tangent);
  EXPECT_EQ(spec.solid->hourglass_min_scale, 0.1);
  // defaults: the source's densities
  const model::BraceSpec defaults = parse_brace(cased_brace(json::object()).dump(), "brace.json");
  ASSERT_TRUE(defaults.solid.has_value());
  EXPECT_EQ(defaults.solid->steel_density, 7.85e-9);
  EXPECT_EQ(defaults.solid->mortar_density, 2.35e-9);
  EXPECT_EQ(defaults.solid->tube, model::SolidTube::elements);
  EXPECT_EQ(defaults.solid->end_faces, model::SolidEndFaces::centre_lines);
  EXPECT_EQ(defaults.solid->hourglass, model::SolidHourglass::elastic);
  EXPECT_EQ(defaults.solid->hourglass_min_scale, 0.05);
  EXPECT_FALSE(parse_brace(cased_brace(json::object()).dump(), "b").solid->half_length);
  EXPECT_EQ(parse_brace(cased_brace({{"end_faces", "pinned"}}).dump(), "b").solid->end_faces,
            model::SolidEndFaces::pinned);
}

TEST(BraceSolidInput, ReportsEachBadMeshInput) {
  std::string message;
  EXPECT_EQ(error_location(cased_brace({{"steel_density", -7.85e-9}}), &message),
            "/solid/steel_density");
  EXPECT_NE(message.find("> 0"), std::string::npos) << message;
  EXPECT_EQ(error_location(cased_brace({{"mortar_density", 0.0}})), "/solid/mortar_density");
  EXPECT_EQ(error_location(cased_brace({{"elements_across_core", 1}}), &message),
            "/solid/elements_across_core");
  EXPECT_NE(message.find("at least 2"), std::string::npos) << message;
  EXPECT_EQ(error_location(cased_brace({{"elements_through_mortar", 1}})),
            "/solid/elements_through_mortar");
  EXPECT_EQ(error_location(cased_brace({{"axial_element_size", 150.0}}), &message),
            "/solid/axial_element_size");
  EXPECT_NE(message.find("aspect ratio"), std::string::npos) << message;
  EXPECT_EQ(error_location(cased_brace({{"tube", "shell"}})), "/solid/tube");
  EXPECT_EQ(error_location(cased_brace({{"half_length", 1}})), "/solid/half_length");
  EXPECT_EQ(error_location(cased_brace({{"end_faces", "grips"}}), &message), "/solid/end_faces");
  EXPECT_NE(message.find("centre_lines"), std::string::npos) << message;
  EXPECT_NE(message.find("pinned"), std::string::npos) << message;
  EXPECT_EQ(error_location(cased_brace({{"mass_scaling", 0.5}})), "/solid/mass_scaling");
  EXPECT_EQ(error_location(cased_brace({{"elements", 3}})), "/solid/elements");
  EXPECT_EQ(error_location(cased_brace({{"hourglass", "plastic"}}), &message), "/solid/hourglass");
  EXPECT_NE(message.find("tangent"), std::string::npos) << message;
  EXPECT_EQ(error_location(cased_brace({{"hourglass_min_scale", 0.0}}), &message),
            "/solid/hourglass_min_scale");
  EXPECT_NE(message.find("(0, 1]"), std::string::npos) << message;
  EXPECT_EQ(error_location(cased_brace({{"hourglass_min_scale", 1.5}})),
            "/solid/hourglass_min_scale");

  json negative_gap = cased_brace(json::object());
  negative_gap["casing"]["gap"] = -0.5;
  EXPECT_EQ(error_location(negative_gap), "/casing/gap");
  json bowed = cased_brace(json::object()); // the bow leaves no mortar along z
  bowed["imperfection"]["amplitude"] = 25.0;
  EXPECT_EQ(error_location(bowed, &message), "/casing/tube");
  EXPECT_NE(message.find("no room for mortar"), std::string::npos) << message;
  json thin_arm = cased_brace(json::object());
  thin_arm["core"]["section"] = {
      {"shape", "cruciform"}, {"width", 12.0}, {"depth", 12.0}, {"thickness", 10.0}};
  EXPECT_EQ(error_location(thin_arm, &message), "/solid/elements_across_core");
  EXPECT_NE(message.find("arm"), std::string::npos) << message;
}

} // namespace
} // namespace brb::io
