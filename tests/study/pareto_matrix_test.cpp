// Reading the settings matrix of `brb bench pareto`: the settings, the reference (the finest
// `full` one unless named) and the errors, each naming the file and the JSON path.
#include "brb/io/input_error.hpp"
#include "brb/study/pareto_matrix.hpp"
#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace {

using namespace brb::study;
using brb::testing::ScratchDirectory;
using nlohmann::json;

const std::string kBrace = BRB_SOURCE_DIR "/examples/braces/plate_core_bare.json";
const std::string kProtocol = BRB_SOURCE_DIR "/examples/protocols/increasing_dy.json";

json component_matrix() {
  return {{"name", "plate"},
          {"kind", "component"},
          {"brace", kBrace},
          {"protocol", kProtocol},
          {"repeats", 3},
          {"settings",
           {{{"label", "truss"}, {"fidelity", "truss"}},
            {{"label", "full-4"}, {"fidelity", "full"}, {"core_elements", 4}},
            {{"label", "full-8"}, {"fidelity", "full"}, {"core_elements", 8}, {"max_step", 0.2}},
            {{"label", "full-8-fine"},
             {"fidelity", "full"},
             {"core_elements", 8},
             {"fibers", {6, 6}},
             {"repeats", 1}},
            {{"label", "auto"}, {"fidelity", "auto"}}}}};
}

/// The error message of reading `matrix`, or "" when it reads.
std::string error_of(const json& matrix) {
  const ScratchDirectory scratch;
  const auto file = scratch.write("m.json", matrix.dump());
  try {
    (void)read_pareto_matrix(file);
  } catch (const brb::io::InputError& error) {
    EXPECT_EQ(error.file(), file.string());
    return error.what();
  }
  return "";
}

TEST(ParetoMatrix, ReadsSettingsAndPicksTheFinestFullAsReference) {
  const ScratchDirectory scratch;
  const ParetoCase study_case =
      read_pareto_matrix(scratch.write("m.json", component_matrix().dump()));
  EXPECT_EQ(study_case.name, "plate");
  EXPECT_EQ(study_case.kind, CaseKind::component);
  EXPECT_EQ(study_case.repeats, 3);
  ASSERT_EQ(study_case.settings.size(), 5u);
  // full-8-fine: 8 elements like full-8, but 36 fibers against the file's: the finest
  EXPECT_EQ(study_case.settings[study_case.reference].label, "full-8-fine");
  EXPECT_EQ(study_case.settings[2].max_step, 0.2);
  EXPECT_EQ(study_case.settings[3].fibers, (std::pair{6, 6}));
  EXPECT_EQ(study_case.settings[3].repeats, 1);
  EXPECT_EQ(study_case.settings[4].fidelity, SettingFidelity::automatic);

  // the setting applied to a brace
  brb::model::BraceSpec brace;
  brace.core_elements = 16;
  brace.core_section.fibers_a = 2;
  const brb::model::BraceSpec applied = study_case.settings[3].applied_to(brace);
  EXPECT_EQ(applied.core_elements, 8);
  EXPECT_EQ(applied.core_section.fibers_a, 6);
  EXPECT_EQ(study_case.settings[0].applied_to(brace).core_elements, 16);

  // a component's full brace is the expanded model unless a setting asks it condensed
  EXPECT_EQ(study_case.settings[1].mode, brb::model::ElementMode::expanded);
  json condensed = component_matrix();
  condensed["settings"][1]["mode"] = "condensed";
  EXPECT_EQ(read_pareto_matrix(scratch.write("c.json", condensed.dump())).settings[1].mode,
            brb::model::ElementMode::condensed);

  json named = component_matrix();
  named["reference"] = "full-4";
  const ParetoCase with_reference = read_pareto_matrix(scratch.write("n.json", named.dump()));
  EXPECT_EQ(with_reference.settings[with_reference.reference].label, "full-4");
}

TEST(ParetoMatrix, ErrorsNameTheJsonPathAndWhatWasExpected) {
  json matrix = component_matrix();
  matrix["reference"] = "truss";
  EXPECT_NE(error_of(matrix).find("/reference: the reference must be a full setting"),
            std::string::npos);

  matrix = component_matrix();
  matrix["reference"] = "nothing";
  EXPECT_NE(error_of(matrix).find("/reference: reference \"nothing\" is not the label"),
            std::string::npos);

  matrix = component_matrix();
  matrix["settings"][1]["label"] = "truss";
  EXPECT_NE(error_of(matrix).find("/settings/1: duplicate setting label \"truss\""),
            std::string::npos);

  matrix = component_matrix();
  matrix["settings"][1]["mode"] = "sideways";
  EXPECT_NE(error_of(matrix).find("/settings/1/mode: mode must be \"condensed\" or "
                                  "\"expanded\" (got \"sideways\")"),
            std::string::npos);

  matrix = component_matrix();
  matrix["settings"][1]["core_elements"] = 0;
  EXPECT_NE(error_of(matrix).find("/settings/1/core_elements: core elements must be a whole "
                                  "number from 1"),
            std::string::npos);

  matrix = component_matrix();
  matrix["settings"][0]["fidelity"] = "exact";
  EXPECT_NE(error_of(matrix).find("/settings/0/fidelity: fidelity must be \"truss\", \"full\" "
                                  "or \"auto\" (got \"exact\")"),
            std::string::npos);

  matrix = component_matrix();
  matrix["brace"] = "/no/such/brace.json";
  EXPECT_NE(error_of(matrix).find("/brace: brace: no such file"), std::string::npos);

  matrix = component_matrix();
  matrix["colour"] = "red";
  EXPECT_NE(error_of(matrix).find("/colour: unknown key"), std::string::npos);

  matrix = component_matrix();
  matrix["solid"] = "/no/such/summary.json";
  EXPECT_NE(error_of(matrix).find("/solid: summary.json of a brb solid run: no such file"),
            std::string::npos);

  matrix = component_matrix();
  matrix["duration"] = 3;
  EXPECT_NE(error_of(matrix).find("/duration: \"duration\" does not apply to a component case"),
            std::string::npos);

  matrix = component_matrix();
  matrix["settings"] = {{{"label", "truss"}, {"fidelity", "truss"}}};
  EXPECT_NE(error_of(matrix).find("/settings: the matrix needs a full setting"), std::string::npos);

  matrix = {{"name", "frame"}, {"kind", "frame"}, {"settings", json::array()}};
  EXPECT_NE(error_of(matrix).find(": missing required key"), std::string::npos);
}

TEST(ParetoMatrix, QuickCaseShortensTheWindowAndRunsOnce) {
  ParetoCase study_case;
  study_case.kind = CaseKind::frame;
  study_case.duration = 3.0;
  study_case.repeats = 5;
  study_case.quick_duration = 0.5;
  ParetoSetting full;
  full.label = "full";
  full.repeats = 3;
  study_case.settings.push_back(full);
  const ParetoCase quick = study_case.quick();
  EXPECT_EQ(quick.duration, 0.5);
  EXPECT_EQ(quick.repeats, 1);
  EXPECT_FALSE(quick.settings.back().repeats.has_value());
}

} // namespace
