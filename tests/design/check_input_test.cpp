// Check files (README "brb check"): what is read, the defaults, and clear errors naming the
// file, the JSON path and what was expected.
#include "brb/design/check_input.hpp"
#include "brb/io/input_error.hpp"

#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>

#include <string>

namespace brb::design {
namespace {

using testing::ScratchDirectory;

const std::string kBrace =
    std::string(BRB_SOURCE_DIR) + "/examples/braces/girona_D3_restrained.json";
const std::string kFrame = std::string(BRB_SOURCE_DIR) + "/frames/brbf3/model.json";

std::string with_brace(const std::string& rest) {
  return "{\"brace\": \"" + kBrace + "\", \"story\": {\"height\": 3000, \"bay_width\": 4000}, " +
         rest + "}";
}

/// The InputError of reading `text` as check.json; fails the test when there is none.
io::InputError error_of(const std::string& text) {
  const ScratchDirectory scratch;
  const auto file = scratch.write("check.json", text);
  try {
    (void)read_check(file);
  } catch (const io::InputError& error) {
    EXPECT_EQ(error.file(), file.string());
    return error;
  }
  ADD_FAILURE() << "no error for " << text;
  return io::InputError("", "", "");
}

TEST(CheckInput, ReadsAStoryCheckWithItsDefaults) {
  const ScratchDirectory scratch;
  const auto file = scratch.write("mine.json", with_brace("\"design_drift\": {\"ratio\": 0.015}"));
  const CheckSpec check = read_check(file);
  EXPECT_EQ(check.name, "mine");
  EXPECT_EQ(check.edition.edition, Edition::aisc341_16); // default edition
  EXPECT_DOUBLE_EQ(check.Ry, 1.0);
  // No Fysc: the brace's own steel is the measured one.
  ASSERT_TRUE(check.fysc_measured.has_value());
  EXPECT_DOUBLE_EQ(*check.fysc_measured, 275.0);
  EXPECT_FALSE(check.fysc_specified.has_value());
  EXPECT_DOUBLE_EQ(check.design_story_drift(), 45.0);
  EXPECT_EQ(check.story.configuration, BraceConfiguration::diagonal);
  EXPECT_FALSE(check.drift_capacity.has_value());
  EXPECT_DOUBLE_EQ(check.beta_limit(), 1.3);
}

TEST(CheckInput, ElasticDriftIsAmplifiedByCdOverIe) {
  const ScratchDirectory scratch;
  const auto file = scratch.write(
      "c.json", with_brace("\"design_drift\": {\"elastic_drift\": 6, \"Cd\": 5, \"Ie\": 1.25}, "
                           "\"edition\": \"341-05\", \"Ry\": 1.1, "
                           "\"Fysc\": {\"specified\": 250}, \"drift_capacity\": {}"));
  const CheckSpec check = read_check(file);
  // ASCE 7-16 (12.8-15): 5 x 6 / 1.25 = 24 mm.
  EXPECT_DOUBLE_EQ(check.design_story_drift(), 24.0);
  EXPECT_EQ(check.edition.edition, Edition::aisc341_05);
  EXPECT_DOUBLE_EQ(*check.fysc_specified, 250.0);
  EXPECT_FALSE(check.fysc_measured.has_value());
  ASSERT_TRUE(check.drift_capacity.has_value());
  EXPECT_DOUBLE_EQ(check.drift_capacity->resolution, 0.0025);
}

TEST(CheckInput, ReadsAFrameBraceAndItsStory) {
  const ScratchDirectory scratch;
  const auto file = scratch.write("c.json", "{\"frame\": {\"model\": \"" + kFrame +
                                                "\", \"brace\": 2201}, "
                                                "\"design_drift\": {\"ratio\": 0.02}}");
  const CheckSpec check = read_check(file);
  ASSERT_TRUE(check.frame_brace.has_value());
  EXPECT_EQ(check.frame_brace->story, "2");
  EXPECT_DOUBLE_EQ(check.story.story_height, 4000.0);
  EXPECT_EQ(check.brace.name, "brbf3_story2");
  EXPECT_EQ(check.brace.element.fidelity, model::Fidelity::full);
}

TEST(CheckInput, NegativeDriftIsAnError) {
  const io::InputError error = error_of(with_brace("\"design_drift\": {\"drift\": -10}"));
  EXPECT_EQ(error.location(), "/design_drift/drift");
  EXPECT_NE(error.expected().find("must be >= 0 mm"), std::string::npos) << error.what();
  EXPECT_NE(error.expected().find("-10"), std::string::npos) << error.what();
}

TEST(CheckInput, RyBelowOneIsAnError) {
  const io::InputError error =
      error_of(with_brace("\"design_drift\": {\"ratio\": 0.01}, \"Ry\": 0.9"));
  EXPECT_EQ(error.location(), "/Ry");
  EXPECT_NE(error.expected().find("must be >= 1"), std::string::npos) << error.what();
  EXPECT_NE(error.expected().find("0.9"), std::string::npos) << error.what();
}

TEST(CheckInput, UnknownEditionIsAnError) {
  const io::InputError error =
      error_of(with_brace("\"design_drift\": {\"ratio\": 0.01}, \"edition\": \"341-99\""));
  EXPECT_EQ(error.location(), "/edition");
  EXPECT_NE(error.expected().find("unknown edition \"341-99\""), std::string::npos);
  EXPECT_NE(error.expected().find("341-05, 341-10, 341-16, 341-22"), std::string::npos)
      << error.what();
}

TEST(CheckInput, BraceIdNotInTheFrameIsAnError) {
  const io::InputError error =
      error_of("{\"frame\": {\"model\": \"" + kFrame +
               "\", \"brace\": 101}, \"design_drift\": {\"ratio\": 0.02}}");
  EXPECT_EQ(error.location(), "/frame/brace");
  EXPECT_NE(error.expected().find("brace id 101 is not a brb element of the frame"),
            std::string::npos)
      << error.what();
  EXPECT_NE(error.expected().find("expected one of: 2101, 2102, 2201, 2202, 2301, 2302"),
            std::string::npos)
      << error.what();
}

TEST(CheckInput, OtherMistakesAreNamedAtTheirPath) {
  struct Case {
    std::string text;
    std::string location;
    std::string expected;
  };
  const std::vector<Case> cases{
      {with_brace("\"design_drift\": {\"ratio\": 0.01}, \"colour\": 1"), "/colour", "unknown key"},
      {with_brace("\"design_drift\": {\"ratio\": 0.01, \"drift\": 5}"), "/design_drift",
       "exactly one of"},
      {with_brace("\"design_drift\": {\"elastic_drift\": 5, \"Cd\": 5, \"Ie\": 0.5}"),
       "/design_drift/Ie", "must be >= 1"},
      {with_brace("\"design_drift\": {\"ratio\": 0.01}, \"Fysc\": {\"specified\": -250}"),
       "/Fysc/specified", "must be > 0 MPa"},
      {with_brace("\"design_drift\": {\"ratio\": 0.01}, \"beta_limit\": 0.8"), "/beta_limit",
       "must be >= 1"},
      {"{\"brace\": \"" + kBrace + "\", \"design_drift\": {\"ratio\": 0.01}}", "top level",
       "missing \"story\""},
      {"{\"brace\": \"" + kBrace +
           "\", \"story\": {\"height\": 3000, \"bay_width\": 4000, \"configuration\": \"x\"}, "
           "\"design_drift\": {\"ratio\": 0.01}}",
       "/story/configuration", "\"diagonal\" or \"chevron\""},
      {with_brace("\"design_drift\": {\"ratio\": 0.01}, \"frame\": {}"), "/brace",
       "not used with \"frame\""},
  };
  for (const Case& c : cases) {
    const io::InputError error = error_of(c.text);
    EXPECT_EQ(error.location(), c.location) << error.what();
    EXPECT_NE(error.expected().find(c.expected), std::string::npos) << error.what();
  }
}

} // namespace
} // namespace brb::design
