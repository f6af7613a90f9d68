// metrics.json of a validation specimen: a valid file read into a Specimen (with the record's
// "shared:" path resolved and its units converted), and every kind of error named by file and
// JSON path; the refinement of a brace; the contrasts file.
#include "brb/io/input_error.hpp"
#include "brb/validation/contrast.hpp"
#include "brb/validation/specimen.hpp"
#include "brb/validation/specimen_run.hpp"
#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <string>

namespace {

namespace fs = std::filesystem;
using brb::io::InputError;
using brb::testing::ScratchDirectory;
using brb::validation::read_specimen;
using brb::validation::Specimen;
using brb::validation::Tolerance;
using nlohmann::json;

/// A valid metrics.json of specimen "bar" with one metric of each check style.
json valid_metrics() {
  return json::parse(R"({
    "id": "bar", "title": "a bar", "source": "a test",
    "brace": "brace.json", "protocol": "protocol.json",
    "refinements": [1, 2, 4],
    "notes": ["an assumption"],
    "metrics": [
      {"name": "energy", "kind": "cycle_energy", "amplitude_dy": 5, "reference": 4477444.559,
       "unit": "N mm", "tolerance": {"relative": 0.05}, "source": "facts 7"},
      {"name": "damage", "kind": "max_indicator", "indicator": "max_mortar_damage",
       "at_most": 0.1, "unit": "-"},
      {"name": "buckling", "kind": "flag", "flag": "global_buckling", "expected": false},
      {"name": "beta", "kind": "compression_tension_ratio", "cycle": 3},
      {"name": "yield", "kind": "yield_force", "direction": "compression",
       "offset_core_strain": 0.002, "reference": 2e6, "tolerance": {"absolute": 1e5}}
    ]})");
}

/// A specimen folder "bar" in `scratch` with `metrics`, empty brace and protocol files (their
/// content is read by the run, not by read_specimen) and a text file.
fs::path write_specimen(const ScratchDirectory& scratch, const json& metrics) {
  const fs::path folder = scratch.path() / "bar";
  fs::create_directories(folder);
  scratch.write("bar/brace.json", "{}");
  scratch.write("bar/protocol.json", "{}");
  scratch.write("bar/readme.txt", "not a protocol");
  scratch.write("bar/metrics.json", "// comments allowed\n" + metrics.dump(2));
  return folder;
}

TEST(Specimen, ReadsAValidFile) {
  const ScratchDirectory scratch;
  const fs::path folder = write_specimen(scratch, valid_metrics());
  const Specimen specimen = read_specimen(folder, scratch.path());
  EXPECT_EQ(specimen.id, "bar");
  EXPECT_EQ(specimen.brace_file, folder / "brace.json");
  EXPECT_EQ(specimen.refinements, (std::vector<int>{1, 2, 4}));
  ASSERT_EQ(specimen.metrics.size(), 5u);
  EXPECT_EQ(*specimen.metrics[0].reference, 4477444.559);
  EXPECT_EQ(specimen.metrics[0].tolerance->kind, Tolerance::Kind::relative);
  EXPECT_EQ(*specimen.metrics[1].at_most, 0.1);
  EXPECT_EQ(*specimen.metrics[2].expected, false);
  EXPECT_FALSE(specimen.metrics[3].reference);
  EXPECT_EQ(specimen.metrics[4].tolerance->kind, Tolerance::Kind::absolute);
  EXPECT_FALSE(specimen.record);
  EXPECT_EQ(specimen.balance_tolerance, 0.0); // the balance control is off unless asked

  json with_solver = valid_metrics();
  with_solver["solver"] = {{"balance_tolerance", 5e-7}};
  const fs::path other = write_specimen(scratch, with_solver);
  EXPECT_EQ(read_specimen(other, scratch.path()).balance_tolerance, 5e-7);
}

TEST(Specimen, ResolvesASharedRecordAndConvertsItsUnits) {
  const ScratchDirectory scratch;
  fs::create_directories(scratch.path() / "shared" / "data");
  scratch.write("shared/data/record.csv", "Force[kip],Deformation[in]\n0,0\n");
  json metrics = valid_metrics();
  metrics["reference"] = {
      {"file", "shared:data/record.csv"},
      {"columns", {{"force", "Force[kip]"}, {"deformation", "Deformation[in]"}}},
      {"units", {{"force", "kip"}, {"length", "in"}}}};
  const Specimen specimen =
      read_specimen(write_specimen(scratch, metrics), scratch.path() / "shared");
  ASSERT_TRUE(specimen.record);
  EXPECT_EQ(specimen.record->source.file, scratch.path() / "shared" / "data" / "record.csv");
  EXPECT_EQ(specimen.record->source.format.force_column, "Force[kip]");
  EXPECT_EQ(specimen.record->source.format.force_unit, "kip");
  EXPECT_EQ(specimen.record->source.format.length_unit, "in");
  EXPECT_EQ(specimen.record->written, "shared:data/record.csv");
  // 1 kip = 1000 lbf = 4448.2216152605 N (exact by the definition of the pound-force);
  // 1 in = 25.4 mm exactly (the reader converts at the edge).
  const brb::io::ForceRecord record =
      brb::io::read_force_record(specimen.record->source.file, specimen.record->source.format);
  ASSERT_EQ(record.size(), 1u);
}

struct InvalidMetricsCase {
  std::string name;
  std::function<void(json&)> spoil;
  std::string path; ///< the JSON path the message must name
};

class InvalidMetrics : public ::testing::TestWithParam<InvalidMetricsCase> {};

TEST_P(InvalidMetrics, NamesTheFileAndTheJsonPath) {
  const ScratchDirectory scratch;
  json metrics = valid_metrics();
  GetParam().spoil(metrics);
  const fs::path folder = write_specimen(scratch, metrics);
  try {
    read_specimen(folder, scratch.path());
    FAIL() << "accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), (folder / "metrics.json").string()) << error.what();
    EXPECT_EQ(error.location(), GetParam().path) << error.what();
  }
}

const json kRecord = {{"file", "shared:missing.csv"},
                      {"columns", {{"force", "F"}, {"deformation", "D"}}},
                      {"units", {{"force", "kip"}, {"length", "in"}}}};

INSTANTIATE_TEST_SUITE_P(
    Schema, InvalidMetrics,
    ::testing::Values(
        InvalidMetricsCase{"IdNotTheFolder", [](json& m) { m["id"] = "other"; }, "/id"},
        InvalidMetricsCase{"UnknownTopKey", [](json& m) { m["colour"] = 1; }, "/colour"},
        InvalidMetricsCase{"MissingBraceFile", [](json& m) { m["brace"] = "nope.json"; }, "/brace"},
        InvalidMetricsCase{"ProtocolOfAnotherType", [](json& m) { m["protocol"] = "readme.txt"; },
                           "/protocol"},
        InvalidMetricsCase{"ZeroRefinement",
                           [](json& m) {
                             m["refinements"] = {1, 0};
                           },
                           "/refinements/1"},
        InvalidMetricsCase{"NoRefinement", [](json& m) { m["refinements"] = json::array(); },
                           "/refinements"},
        InvalidMetricsCase{"BalanceToleranceNegative",
                           [](json& m) {
                             m["solver"] = {{"balance_tolerance", -1e-7}};
                           },
                           "/solver/balance_tolerance"},
        InvalidMetricsCase{"UnknownSolverKey",
                           [](json& m) {
                             m["solver"] = {{"energy_tolerance", 1e-7}};
                           },
                           "/solver/energy_tolerance"},
        InvalidMetricsCase{"UnknownKind", [](json& m) { m["metrics"][0]["kind"] = "energy"; },
                           "/metrics/0/kind"},
        InvalidMetricsCase{"UnknownMetricKey",
                           [](json& m) { m["metrics"][3]["direction"] = "tension"; },
                           "/metrics/3/direction"},
        InvalidMetricsCase{"CycleEnergyWithoutCycle",
                           [](json& m) { m["metrics"][0].erase("amplitude_dy"); }, "/metrics/0"},
        InvalidMetricsCase{"TwoCycleSelectors", [](json& m) { m["metrics"][0]["cycle"] = 2; },
                           "/metrics/0/amplitude_dy"},
        InvalidMetricsCase{"CycleNotWhole", [](json& m) { m["metrics"][3]["cycle"] = 1.5; },
                           "/metrics/3/cycle"},
        InvalidMetricsCase{"ReferenceWithoutTolerance",
                           [](json& m) { m["metrics"][0].erase("tolerance"); },
                           "/metrics/0/reference"},
        InvalidMetricsCase{"ToleranceOfBothKinds",
                           [](json& m) { m["metrics"][0]["tolerance"]["absolute"] = 1; },
                           "/metrics/0/tolerance"},
        InvalidMetricsCase{"NegativeTolerance",
                           [](json& m) { m["metrics"][0]["tolerance"]["relative"] = -0.1; },
                           "/metrics/0/tolerance/relative"},
        InvalidMetricsCase{"FlagWithReference", [](json& m) { m["metrics"][2]["reference"] = 1; },
                           "/metrics/2/reference"},
        InvalidMetricsCase{"FlagWithoutExpected",
                           [](json& m) { m["metrics"][2].erase("expected"); }, "/metrics/2"},
        InvalidMetricsCase{"ExpectedNotBoolean",
                           [](json& m) { m["metrics"][2]["expected"] = "no"; },
                           "/metrics/2/expected"},
        InvalidMetricsCase{"UnknownFlag", [](json& m) { m["metrics"][2]["flag"] = "collapse"; },
                           "/metrics/2/flag"},
        InvalidMetricsCase{"UnknownIndicator",
                           [](json& m) { m["metrics"][1]["indicator"] = "damage"; },
                           "/metrics/1/indicator"},
        InvalidMetricsCase{"DirectionMissing", [](json& m) { m["metrics"][4].erase("direction"); },
                           "/metrics/4/direction"},
        InvalidMetricsCase{"BoundsCrossed", [](json& m) { m["metrics"][1]["at_least"] = 0.5; },
                           "/metrics/1/at_most"},
        InvalidMetricsCase{"MetricNamedTwice", [](json& m) { m["metrics"][1]["name"] = "energy"; },
                           "/metrics/1/name"},
        InvalidMetricsCase{"RecordFileMissing", [](json& m) { m["reference"] = kRecord; },
                           "/reference/file"},
        InvalidMetricsCase{"RecordForceUnit",
                           [](json& m) {
                             m["reference"] = kRecord;
                             m["reference"]["file"] = "brace.json";
                             m["reference"]["units"]["force"] = "lbf";
                           },
                           "/reference/units/force"}),
    [](const auto& info) { return info.param.name; });

TEST(Refinement, MultipliesEveryZonesElementCount) {
  brb::model::BraceSpec spec;
  spec.core_elements = 16;
  spec.transition = brb::model::ZoneSpec{};
  spec.transition->elements = 1;
  spec.connection = brb::model::ZoneSpec{};
  spec.connection->elements = 2;
  const brb::model::BraceSpec finer = brb::validation::refined(spec, 4);
  EXPECT_EQ(finer.core_elements, 64);
  EXPECT_EQ(finer.transition->elements, 4);
  EXPECT_EQ(finer.connection->elements, 8);
}

TEST(RefinementList, ParsesAndRejects) {
  EXPECT_EQ(brb::validation::parse_refinement_list("1,2,4"), (std::vector<int>{1, 2, 4}));
  EXPECT_EQ(brb::validation::parse_refinement_list("2,2"), (std::vector<int>{2}));
  EXPECT_THROW(brb::validation::parse_refinement_list("1,x"), std::invalid_argument);
  EXPECT_THROW(brb::validation::parse_refinement_list("0"), std::invalid_argument);
  EXPECT_THROW(brb::validation::parse_refinement_list(""), std::invalid_argument);
}

TEST(Contrasts, OperandsMustNameAKnownSpecimenAndANumericMetric) {
  const ScratchDirectory scratch;
  const Specimen specimen = read_specimen(write_specimen(scratch, valid_metrics()), scratch.path());
  const auto contrasts_with = [&](const json& left) {
    json contrast = {{"name", "c"},       {"statement", "s"},
                     {"source", "facts"}, {"left", left},
                     {"relation", ">"},   {"right", {{"specimen", "bar"}, {"metric", "beta"}}}};
    return scratch.write("contrasts.json", json{{"contrasts", {contrast}}}.dump());
  };
  const auto location_of = [&](const json& left) {
    try {
      brb::validation::read_contrasts(contrasts_with(left), {specimen});
    } catch (const InputError& error) {
      return error.location();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(location_of({{"specimen", "bar"}, {"metric", "energy"}}), "accepted");
  EXPECT_EQ(location_of({{"specimen", "baz"}, {"metric", "energy"}}), "/contrasts/0/left/specimen");
  EXPECT_EQ(location_of({{"specimen", "bar"}, {"metric", "nothing"}}), "/contrasts/0/left/metric");
  EXPECT_EQ(location_of({{"specimen", "bar"}, {"metric", "buckling"}}), "/contrasts/0/left/metric");
}

} // namespace
