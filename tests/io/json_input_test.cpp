// JSON helpers: pointers, parameter paths and error locations.
#include "brb/io/json_input.hpp"
#include "brb/io/material_input.hpp"

#include <gtest/gtest.h>

namespace brb::io {
namespace {

TEST(JsonPointer, AppendsAndEscapesTokens) {
  EXPECT_EQ(json_pointer_append("", "fy"), "/fy");
  EXPECT_EQ(json_pointer_append("/chaboche", "1"), "/chaboche/1");
  EXPECT_EQ(json_pointer_append("", "a/b~c"), "/a~1b~0c");
}

TEST(ParameterPath, FollowsTheKeysOfTheInputFile) {
  EXPECT_EQ(json_path_of_parameter("fy"), "/fy");
  EXPECT_EQ(json_path_of_parameter("chaboche[1].C"), "/chaboche/1/C");
  EXPECT_EQ(json_path_of_parameter("chaboche[12].gamma"), "/chaboche/12/gamma");
  EXPECT_EQ(json_path_of_parameter("voce.Q"), "/voce/Q");
}

TEST(ParameterPath, ParameterErrorBecomesInputErrorWithTheGivenValue) {
  const ParameterSource source{"p.json", nlohmann::json::parse(R"({"voce": {"Q": -40}})")};
  const InputError error = input_error_from(ParameterError("voce.Q", "must be >= 0 MPa"), source);
  EXPECT_EQ(error.file(), "p.json");
  EXPECT_EQ(error.location(), "/voce/Q");
  EXPECT_STREQ(error.what(), "p.json: /voce/Q: must be >= 0 MPa (got -40)");
}

TEST(JsonValue, NumbersMustBeFinite) {
  EXPECT_THROW(parse_json(R"({"E": 1e999})", "p.json"), InputError);
  const auto document = parse_json(R"({"E": 1e300})", "p.json");
  EXPECT_EQ(JsonValue(document, "p.json").at("E", "E").number("E"), 1e300);
}

TEST(JsonValue, ErrorsAtTheDocumentAreAtTopLevel) {
  const auto document = parse_json("[1, 2]", "p.json");
  try {
    JsonValue(document, "p.json").expect_object({"E"}, "an object");
    FAIL() << "an array was taken for an object";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "top level");
  }
}

TEST(JsonValue, EmptyTextIsAnInputError) {
  EXPECT_THROW(parse_json("", "empty.json"), InputError);
  EXPECT_THROW(parse_json("// only a comment\n", "empty.json"), InputError);
}

TEST(JsonValue, DuplicateKeysAreErrorsAtTheirPath) {
  const auto location_of = [](const std::string& text) {
    try {
      parse_json(text, "p.json");
    } catch (const InputError& error) {
      return error.location();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(location_of(R"({"fy": 275, "E": 210000, "fy": 355})"), "/fy");
  EXPECT_EQ(location_of(R"({"chaboche": [{"C": 1, "gamma": 2}, {"C": 1, "C": 2}]})"),
            "/chaboche/1/C");
  EXPECT_EQ(location_of(R"({"a": [[1, 2], {"b": {"c": 1}}, {"d": 1, "d": 2}]})"), "/a/2/d");
  EXPECT_EQ(location_of(R"({"voce": {"Q": 1}, "Q": 2, "b": [{"Q": 1}]})"), "accepted");
}

} // namespace
} // namespace brb::io
