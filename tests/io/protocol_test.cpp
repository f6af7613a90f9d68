// Loading protocols: the built-in Girona and UC San Diego sequences (BRB_SOURCE_FACTS sections
// 7 and 8), cycles of given amplitudes, protocol JSON files and CSV histories (the schema at
// the top of brb/io/protocol.hpp), and every invalid input reported as an InputError naming
// the file and the JSON path.
#include "brb/io/csv.hpp"
#include "brb/io/input_error.hpp"
#include "brb/io/protocol.hpp"
#include "io/scratch_directory.hpp"

#include "support/invalid_json.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace brb::io {
namespace {

using nlohmann::json;

/// Yield deformation of Girona bar D3, fy / E * L_di = 275 / 210000 * 2196 mm
/// (BRB_SOURCE_FACTS section 7).
constexpr double kGironaD3YieldDeformation = 275.0 / 210000.0 * 2196.0;
/// Yield deformation of UC San Diego G1/G2, dy = 0.21 in (BRB_SOURCE_FACTS section 8).
constexpr double kUcsdG1YieldDeformation = 0.21 * 25.4;

/// The largest spacing of consecutive points a protocol with `max_step` may have
/// (step_rounding_tolerance, protocol.hpp).
double spacing_limit(double max_step) {
  return max_step * (1.0 + step_rounding_tolerance);
}

/// Checks what every protocol promises (protocol.hpp): one cycle index per point, a first
/// point 0.0 in cycle 0, cycle indices 1, 2, ... in order, one amplitude per cycle, and
/// consecutive points at most max_step apart.
void expect_well_formed(const LoadingProtocol& protocol, double max_step) {
  const auto& deformation = protocol.deformation;
  ASSERT_FALSE(deformation.empty());
  ASSERT_EQ(protocol.cycle.size(), deformation.size());
  EXPECT_EQ(deformation.front(), 0.0);
  EXPECT_EQ(protocol.cycle.front(), 0);
  for (std::size_t i = 1; i < deformation.size(); ++i) {
    EXPECT_LE(std::abs(deformation[i] - deformation[i - 1]), spacing_limit(max_step))
        << "points " << i - 1 << " and " << i;
    const int step_in_cycle = protocol.cycle[i] - protocol.cycle[i - 1];
    EXPECT_TRUE(step_in_cycle == 0 || step_in_cycle == 1) << "point " << i;
    EXPECT_GE(protocol.cycle[i], 1) << "point " << i;
  }
  EXPECT_EQ(static_cast<std::size_t>(protocol.cycle.back()), protocol.cycle_count());
}

/// Indices of the turning points: the first and last points, every reversal of direction, and
/// the last point of every cycle (the return to zero, after which the next cycle goes on in
/// the same direction).
std::vector<std::size_t> turning_point_indices(const LoadingProtocol& protocol) {
  const auto& deformation = protocol.deformation;
  std::vector<std::size_t> indices{0};
  for (std::size_t i = 1; i + 1 < deformation.size(); ++i) {
    const bool reverses =
        (deformation[i] - deformation[i - 1]) * (deformation[i + 1] - deformation[i]) < 0.0;
    const bool ends_cycle = protocol.cycle[i + 1] != protocol.cycle[i];
    if (reverses || ends_cycle)
      indices.push_back(i);
  }
  indices.push_back(deformation.size() - 1);
  return indices;
}

std::vector<double> turning_points(const LoadingProtocol& protocol) {
  std::vector<double> values;
  for (const std::size_t index : turning_point_indices(protocol)) {
    values.push_back(protocol.deformation[index]);
  }
  return values;
}

/// The turning points of full cycles 0 -> +A -> -A -> 0 at the given amplitudes, in order.
std::vector<double> cycle_turning_points(const std::vector<double>& amplitudes) {
  std::vector<double> values{0.0};
  for (const double amplitude : amplitudes) {
    values.insert(values.end(), {amplitude, -amplitude, 0.0});
  }
  return values;
}

/// Checks that each cycle k peaks at exactly +A_k in tension and -A_k in compression and ends
/// at exactly 0.
void expect_exact_peaks(const LoadingProtocol& protocol, const std::vector<double>& amplitudes) {
  ASSERT_EQ(protocol.cycle_amplitude, amplitudes);
  for (std::size_t k = 1; k <= amplitudes.size(); ++k) {
    double tension_peak = -std::numeric_limits<double>::infinity();
    double compression_peak = std::numeric_limits<double>::infinity();
    double last = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < protocol.deformation.size(); ++i) {
      if (protocol.cycle[i] == static_cast<int>(k)) {
        tension_peak = std::max(tension_peak, protocol.deformation[i]);
        compression_peak = std::min(compression_peak, protocol.deformation[i]);
        last = protocol.deformation[i];
      }
    }
    EXPECT_EQ(tension_peak, amplitudes[k - 1]) << "cycle " << k;
    EXPECT_EQ(compression_peak, -amplitudes[k - 1]) << "cycle " << k;
    EXPECT_EQ(last, 0.0) << "cycle " << k;
  }
}

std::vector<double> scaled(std::vector<double> multiples, double unit) {
  for (double& value : multiples)
    value *= unit;
  return multiples;
}

// Reference: BRB_SOURCE_FACTS section 7 (Girona: 0.25, 0.5, 0.75, 1, 2, 2.5 dy, then 5 dy
// repeated until failure), one cycle per ramp amplitude as protocol.hpp states.
TEST(ProtocolBuiltin, GironaHasSixRampCyclesThenTheFinalCyclesAtFiveDy) {
  const double dy = kGironaD3YieldDeformation;
  const double max_step = 0.05 * dy;
  for (const int final_cycles : {1, 4}) {
    const LoadingProtocol protocol = girona_protocol(dy, final_cycles, max_step);
    EXPECT_EQ(protocol.name, "girona");
    expect_well_formed(protocol, max_step);
    std::vector<double> multiples{0.25, 0.5, 0.75, 1.0, 2.0, 2.5};
    multiples.insert(multiples.end(), static_cast<std::size_t>(final_cycles), 5.0);
    ASSERT_EQ(protocol.cycle_count(), 6u + static_cast<std::size_t>(final_cycles));
    expect_exact_peaks(protocol, scaled(multiples, dy));
    EXPECT_EQ(turning_points(protocol), cycle_turning_points(scaled(multiples, dy)));
  }
}

// Reference: BRB_SOURCE_FACTS section 8 (UC San Diego G series: 5 cycles at dy, 2 at 2 dy, 1
// at 3 dy, 1 at 4 dy), with dy of G1/G2.
TEST(ProtocolBuiltin, UcsdHasNineCyclesFiveAtDyTwoAtTwoDyOneAtThreeDyOneAtFourDy) {
  const double dy = kUcsdG1YieldDeformation;
  const double max_step = 0.1 * dy;
  const LoadingProtocol protocol = ucsd_protocol(dy, max_step);
  EXPECT_EQ(protocol.name, "ucsd");
  expect_well_formed(protocol, max_step);
  const std::vector<double> multiples{1.0, 1.0, 1.0, 1.0, 1.0, 2.0, 2.0, 3.0, 4.0};
  ASSERT_EQ(protocol.cycle_count(), 9u);
  expect_exact_peaks(protocol, scaled(multiples, dy));
  EXPECT_EQ(turning_points(protocol), cycle_turning_points(scaled(multiples, dy)));
}

// Reference: protocol.hpp, cyclic_protocol (equal steps of at most max_step on each leg,
// turning points exact), with amplitudes that are no whole number of steps.
TEST(ProtocolCyclic, SpacingNeverExceedsMaxStepAndTurningPointsAreHitExactly) {
  const double max_step = 0.3;
  const LoadingProtocol protocol =
      cyclic_protocol("test", {{1.0, 1}, {0.37, 2}, {2.9, 1}, {0.01, 1}}, max_step);
  EXPECT_EQ(protocol.name, "test");
  expect_well_formed(protocol, max_step);
  const std::vector<double> amplitudes{1.0, 0.37, 0.37, 2.9, 0.01};
  expect_exact_peaks(protocol, amplitudes);
  EXPECT_EQ(turning_points(protocol), cycle_turning_points(amplitudes));

  // Each leg: the fewest equal steps of at most max_step, ceil(length / max_step).
  const auto turning = turning_point_indices(protocol);
  for (std::size_t leg = 1; leg < turning.size(); ++leg) {
    const double start = protocol.deformation[turning[leg - 1]];
    const double end = protocol.deformation[turning[leg]];
    const std::size_t steps = turning[leg] - turning[leg - 1];
    EXPECT_EQ(steps, static_cast<std::size_t>(std::ceil(std::abs(end - start) / max_step)))
        << "leg " << leg;
    const double equal_step = (end - start) / static_cast<double>(steps);
    for (std::size_t i = turning[leg - 1] + 1; i <= turning[leg]; ++i) {
      EXPECT_NEAR(protocol.deformation[i] - protocol.deformation[i - 1], equal_step,
                  1e-12 * std::abs(end - start))
          << "leg " << leg << ", point " << i;
    }
  }
}

// Reference: protocol.hpp, step_rounding_tolerance: a leg of 1.5 dy in steps of 0.1 dy has 15
// steps even though, with dy of Girona bar D3, 1.5 dy / (0.1 dy) rounds to 15.000000000000002
// (likewise 3 dy and 1.1 dy; 1 dy divides exactly).
TEST(ProtocolCyclic, LegsOfAWholeNumberOfStepsGetNoExtraStepFromRounding) {
  const double dy = kGironaD3YieldDeformation;
  ASSERT_GT(1.5 * dy / (0.1 * dy), 15.0); // the rounding this test is about
  const LoadingProtocol protocol = cyclic_protocol(
      "whole", {{1.0 * dy, 1}, {1.5 * dy, 1}, {3.0 * dy, 1}, {1.1 * dy, 1}}, 0.1 * dy);
  // 10 + 20 + 10, 15 + 30 + 15, 30 + 60 + 30 and 11 + 22 + 11 steps, plus the initial point.
  EXPECT_EQ(protocol.deformation.size(), 1u + 40u + 60u + 120u + 44u);
  expect_well_formed(protocol, 0.1 * dy);
}

// Reference: protocol.hpp, cyclic_protocol: tension first, cycle indices per point.
TEST(ProtocolCyclic, GoesTensionFirstAndNumbersThePointsByCycle) {
  const LoadingProtocol protocol = cyclic_protocol("two", {{1.0, 2}}, 0.5);
  EXPECT_EQ(protocol.deformation,
            (std::vector<double>{0.0, 0.5, 1.0, 0.5, 0.0, -0.5, -1.0, -0.5, 0.0, 0.5, 1.0, 0.5, 0.0,
                                 -0.5, -1.0, -0.5, 0.0}));
  EXPECT_EQ(protocol.cycle, (std::vector<int>{0, 1, 1, 1, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2, 2, 2}));
  EXPECT_EQ(protocol.cycle_amplitude, (std::vector<double>{1.0, 1.0}));
}

// Reference: protocol.hpp (std::invalid_argument for programming errors of the caller).
TEST(ProtocolCyclic, RejectsInvalidArgumentsOfTheCaller) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(cyclic_protocol("x", {}, 0.1), std::invalid_argument);
  EXPECT_THROW(cyclic_protocol("x", {{0.0, 1}}, 0.1), std::invalid_argument);
  EXPECT_THROW(cyclic_protocol("x", {{-1.0, 1}}, 0.1), std::invalid_argument);
  EXPECT_THROW(cyclic_protocol("x", {{nan, 1}}, 0.1), std::invalid_argument);
  EXPECT_THROW(cyclic_protocol("x", {{1.0, 0}}, 0.1), std::invalid_argument);
  EXPECT_THROW(cyclic_protocol("x", {{1.0, 1}}, 0.0), std::invalid_argument);
  EXPECT_THROW(cyclic_protocol("x", {{1.0, 1}}, -0.1), std::invalid_argument);
  EXPECT_THROW(cyclic_protocol("x", {{1.0, 1}}, 1e-12), std::invalid_argument); // too many
  EXPECT_THROW(girona_protocol(0.0, 1, 0.1), std::invalid_argument);
  EXPECT_THROW(girona_protocol(1.0, 0, 0.1), std::invalid_argument);
  EXPECT_THROW(ucsd_protocol(-1.0, 0.1), std::invalid_argument);
  EXPECT_THROW(history_protocol("x", {}, 0.1), std::invalid_argument);
  EXPECT_THROW(history_protocol("x", {0.0, -0.0}, 0.1), std::invalid_argument);
  EXPECT_THROW(history_protocol("x", {1.0, nan}, 0.1), std::invalid_argument);
}

// ---- Protocol JSON files ----

/// A protocol of 0.25, 1.5 and 3 dy (one, two and one cycles) in steps of 0.2 dy, in dy units.
json protocol_in_dy() {
  return {{"units", "dy"},
          {"cycles", json::array({{{"amplitude", 0.25}, {"cycles", 1}},
                                  {{"amplitude", 1.5}, {"cycles", 2}},
                                  {{"amplitude", 3}, {"cycles", 1}}})},
          {"max_step", 0.2}};
}

/// dy = 2.5 mm makes every amplitude and max_step of protocol_in_dy() exact in mm.
constexpr double kExactYieldDeformation = 2.5;

// Reference: protocol.hpp schema ("units": "mm" or "dy", amplitudes and max_step in units).
TEST(ProtocolJson, MillimetresAndYieldDeformationsGiveTheSameHistory) {
  testing::ScratchDirectory scratch;
  const json in_mm = {{"units", "mm"},
                      {"cycles", json::array({{{"amplitude", 0.625}, {"cycles", 1}},
                                              {{"amplitude", 3.75}, {"cycles", 2}},
                                              {{"amplitude", 7.5}, {"cycles", 1}}})},
                      {"max_step", 0.5}};
  const auto dy_file = scratch.write("in_dy.json", protocol_in_dy().dump());
  const auto mm_file = scratch.write("in_mm.json", in_mm.dump());
  const LoadingProtocol from_dy = read_protocol(dy_file, kExactYieldDeformation, 100.0);
  const LoadingProtocol from_mm = read_protocol(mm_file, kExactYieldDeformation, 100.0);

  EXPECT_EQ(from_dy.deformation, from_mm.deformation);
  EXPECT_EQ(from_dy.cycle, from_mm.cycle);
  EXPECT_EQ(from_dy.cycle_amplitude, (std::vector<double>{0.625, 3.75, 3.75, 7.5}));
  EXPECT_EQ(from_mm.cycle_amplitude, from_dy.cycle_amplitude);
  EXPECT_EQ(from_dy.name, dy_file.string());
  expect_well_formed(from_dy, 0.5);
  EXPECT_EQ(from_dy.deformation,
            cyclic_protocol("", {{0.625, 1}, {3.75, 2}, {7.5, 1}}, 0.5).deformation);
}

// Reference: protocol.hpp schema (max_step optional; default: the caller's, in mm).
TEST(ProtocolJson, MaxStepDefaultsToTheCallersInMillimetres) {
  testing::ScratchDirectory scratch;
  json document = protocol_in_dy();
  document.erase("max_step");
  const auto file = scratch.write("p.json", document.dump());
  const double default_max_step = 0.3;
  const LoadingProtocol protocol = read_protocol(file, kExactYieldDeformation, default_max_step);
  expect_well_formed(protocol, default_max_step);
  EXPECT_EQ(protocol.deformation,
            cyclic_protocol("", {{0.625, 1}, {3.75, 2}, {7.5, 1}}, default_max_step).deformation);
}

// Reference: protocol.hpp schema ("builtin": "girona" with "final_cycles", or "ucsd"; max_step
// in "units", default "dy") and BRB_SOURCE_FACTS sections 7 and 8.
TEST(ProtocolJson, BuiltinProtocolsMatchTheLibrarySequences) {
  testing::ScratchDirectory scratch;
  const double dy = kGironaD3YieldDeformation;
  const auto girona =
      scratch.write("girona.json", R"({"builtin": "girona", "final_cycles": 4, "max_step": 0.05})");
  const LoadingProtocol from_file = read_protocol(girona, dy, 1.0);
  const LoadingProtocol expected = girona_protocol(dy, 4, 0.05 * dy);
  EXPECT_EQ(from_file.name, "girona");
  EXPECT_EQ(from_file.deformation, expected.deformation);
  EXPECT_EQ(from_file.cycle, expected.cycle);
  EXPECT_EQ(from_file.cycle_amplitude, expected.cycle_amplitude);

  const auto ucsd_mm =
      scratch.write("ucsd.json", R"({"builtin": "ucsd", "units": "mm", "max_step": 0.5})");
  EXPECT_EQ(read_protocol(ucsd_mm, dy, 1.0).deformation, ucsd_protocol(dy, 0.5).deformation);

  const auto ucsd_default = scratch.write("ucsd_default.json", R"({"builtin": "ucsd"})");
  const LoadingProtocol ucsd = read_protocol(ucsd_default, dy, 0.7);
  EXPECT_EQ(ucsd.name, "ucsd");
  EXPECT_EQ(ucsd.deformation, ucsd_protocol(dy, 0.7).deformation);
}

// Reference: the brief and DESIGN.md section 1 (inputs in other units are converted at the
// edge, never guessed): a protocol whose amplitudes have no units is rejected.
TEST(ProtocolJson, UnitlessProtocolIsRejected) {
  testing::ScratchDirectory scratch;
  json document = protocol_in_dy();
  document.erase("units");
  const auto file = scratch.write("unitless.json", document.dump());
  try {
    read_protocol(file, 2.0, 0.1);
    FAIL() << "a protocol without units was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), file.string());
    EXPECT_EQ(error.location(), "/units");
    const std::string message = error.what();
    EXPECT_NE(message.find("unit-less amplitudes"), std::string::npos) << message;
    EXPECT_NE(message.find("\"mm\""), std::string::npos) << message;
    EXPECT_NE(message.find("\"dy\""), std::string::npos) << message;
  }
}

// Reference: json_input.hpp (comments allowed) and protocol.hpp (cycles: a positive
// integer, which 2.0 is).
TEST(ProtocolJson, AcceptsCommentsAndIntegralCycleCountsWrittenAsDecimals) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("p.json", R"(// two cycles at 1 mm
{ "units": "mm", /* millimetres */
  "cycles": [ {"amplitude": 1, "cycles": 2.0} ], "max_step": 0.5 })");
  EXPECT_EQ(read_protocol(file, 2.0, 0.1).cycle_amplitude, (std::vector<double>{1.0, 1.0}));
}

using InvalidProtocol = test::InvalidJsonCase;
using test::with;
using test::without;

/// protocol_in_dy() with member `key` of cycle group `group` set to `value`.
json with_group_member(std::size_t group, const std::string& key, json value) {
  json document = protocol_in_dy();
  document["cycles"][group][key] = std::move(value);
  return document;
}

json without_group_member(std::size_t group, const std::string& key) {
  json document = protocol_in_dy();
  document["cycles"][group].erase(key);
  return document;
}

json girona_builtin() {
  return {{"builtin", "girona"}, {"final_cycles", 3}};
}

class ProtocolJsonRejects : public ::testing::TestWithParam<InvalidProtocol> {};

// Reference: protocol.hpp schema and DESIGN.md section 7 (every error names the file, the
// JSON path and what was expected).
TEST_P(ProtocolJsonRejects, WithFileAndJsonPath) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("protocol.json", GetParam().document().dump());
  test::expect_rejected_at_path(file, GetParam(),
                                [&] { read_protocol(file, kExactYieldDeformation, 0.1); });
}

INSTANTIATE_TEST_SUITE_P(
    ProtocolEachInvalidInput, ProtocolJsonRejects,
    ::testing::Values(
        InvalidProtocol{"not_an_object",
                        [] {
                          return json::array({1, 2});
                        },
                        "top level"},
        InvalidProtocol{"unknown_key", [] { return with(protocol_in_dy(), "amplitude", 1.0); },
                        "/amplitude"},
        InvalidProtocol{"unknown_key_in_group", [] { return with_group_member(0, "count", 2); },
                        "/cycles/0/count"},
        InvalidProtocol{"neither_cycles_nor_builtin", [] { return json::object(); }, "/cycles"},
        InvalidProtocol{"missing_units", [] { return without(protocol_in_dy(), "units"); },
                        "/units"},
        InvalidProtocol{"units_inches", [] { return with(protocol_in_dy(), "units", "in"); },
                        "/units"},
        InvalidProtocol{"units_not_a_string", [] { return with(protocol_in_dy(), "units", 1); },
                        "/units"},
        InvalidProtocol{"cycles_not_an_array",
                        [] { return with(protocol_in_dy(), "cycles", json::object()); }, "/cycles"},
        InvalidProtocol{"empty_cycles",
                        [] { return with(protocol_in_dy(), "cycles", json::array()); }, "/cycles"},
        InvalidProtocol{"group_not_an_object",
                        [] {
                          json document = protocol_in_dy();
                          document["cycles"][1] = 2.0;
                          return document;
                        },
                        "/cycles/1"},
        InvalidProtocol{"zero_amplitude", [] { return with_group_member(0, "amplitude", 0.0); },
                        "/cycles/0/amplitude"},
        InvalidProtocol{"negative_amplitude",
                        [] { return with_group_member(2, "amplitude", -1.0); },
                        "/cycles/2/amplitude"},
        InvalidProtocol{"amplitude_a_string", [] { return with_group_member(0, "amplitude", "1"); },
                        "/cycles/0/amplitude"},
        InvalidProtocol{"missing_amplitude", [] { return without_group_member(1, "amplitude"); },
                        "/cycles/1/amplitude"},
        InvalidProtocol{"fractional_cycles", [] { return with_group_member(1, "cycles", 1.5); },
                        "/cycles/1/cycles"},
        InvalidProtocol{"zero_cycles", [] { return with_group_member(1, "cycles", 0); },
                        "/cycles/1/cycles"},
        InvalidProtocol{"negative_cycles", [] { return with_group_member(1, "cycles", -1); },
                        "/cycles/1/cycles"},
        InvalidProtocol{"cycles_beyond_int", [] { return with_group_member(0, "cycles", 1e10); },
                        "/cycles/0/cycles"},
        InvalidProtocol{"missing_cycles", [] { return without_group_member(2, "cycles"); },
                        "/cycles/2/cycles"},
        InvalidProtocol{"zero_max_step", [] { return with(protocol_in_dy(), "max_step", 0.0); },
                        "/max_step"},
        InvalidProtocol{"negative_max_step",
                        [] { return with(protocol_in_dy(), "max_step", -0.1); }, "/max_step"},
        InvalidProtocol{"max_step_too_small_for_the_amplitudes",
                        [] { return with(protocol_in_dy(), "max_step", 1e-9); }, "/max_step"},
        InvalidProtocol{"unknown_builtin",
                        [] {
                          return json{{"builtin", "aisc"}};
                        },
                        "/builtin"},
        InvalidProtocol{"builtin_not_a_string",
                        [] {
                          return json{{"builtin", 1}};
                        },
                        "/builtin"},
        InvalidProtocol{"builtin_with_cycles",
                        [] { return with(girona_builtin(), "cycles", protocol_in_dy()["cycles"]); },
                        "/cycles"},
        InvalidProtocol{"builtin_units_inches",
                        [] { return with(girona_builtin(), "units", "in"); }, "/units"},
        InvalidProtocol{"builtin_zero_max_step",
                        [] { return with(girona_builtin(), "max_step", 0.0); }, "/max_step"},
        InvalidProtocol{"girona_without_final_cycles",
                        [] { return without(girona_builtin(), "final_cycles"); }, "/final_cycles"},
        InvalidProtocol{"girona_zero_final_cycles",
                        [] { return with(girona_builtin(), "final_cycles", 0); }, "/final_cycles"},
        InvalidProtocol{"girona_fractional_final_cycles",
                        [] { return with(girona_builtin(), "final_cycles", 2.5); },
                        "/final_cycles"},
        InvalidProtocol{"girona_negative_final_cycles",
                        [] { return with(girona_builtin(), "final_cycles", -1); }, "/final_cycles"},
        InvalidProtocol{"ucsd_with_final_cycles",
                        [] {
                          return json{{"builtin", "ucsd"}, {"final_cycles", 2}};
                        },
                        "/final_cycles"},
        InvalidProtocol{"final_cycles_without_builtin",
                        [] { return with(protocol_in_dy(), "final_cycles", 2); }, "/final_cycles"}),
    [](const ::testing::TestParamInfo<InvalidProtocol>& info) { return info.param.name; });

// Reference: json_input.hpp (a number beyond double range is invalid JSON, so no amplitude
// can be infinite) and DESIGN.md section 7.
TEST(ProtocolJson, AmplitudeBeyondDoubleRangeIsRejectedNamingTheFile) {
  testing::ScratchDirectory scratch;
  const auto file =
      scratch.write("p.json", R"({"units": "mm", "cycles": [{"amplitude": 1e400, "cycles": 1}]})");
  try {
    read_protocol(file, 2.0, 0.1);
    FAIL() << "amplitude 1e400 was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), file.string());
  }
}

// Reference: protocol.hpp, read_protocol (the type of file by its extension).
TEST(ProtocolRead, RejectsOtherFileTypesAndMissingFiles) {
  testing::ScratchDirectory scratch;
  const auto text = scratch.write("protocol.txt", "deformation\n1\n");
  try {
    read_protocol(text, 2.0, 0.1);
    FAIL() << "a .txt protocol was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), text.string());
    EXPECT_NE(std::string(error.what()).find(".json"), std::string::npos) << error.what();
  }
  const auto absent = scratch.path() / "absent.json";
  try {
    read_protocol(absent, 2.0, 0.1);
    FAIL() << "a missing protocol file was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), absent.string());
  }
  // Upper-case extensions are the same types.
  const auto upper = scratch.write("P.JSON", R"({"builtin": "ucsd"})");
  EXPECT_EQ(read_protocol(upper, 2.0, 0.5).cycle_count(), 9u);
}

// Reference: protocol.hpp, read_protocol (std::invalid_argument for the caller's dy and
// default max_step).
TEST(ProtocolRead, RejectsNonPositiveYieldDeformationOrDefaultMaxStep) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("p.json", protocol_in_dy().dump());
  EXPECT_THROW(read_protocol(file, 0.0, 0.1), std::invalid_argument);
  EXPECT_THROW(read_protocol(file, -2.0, 0.1), std::invalid_argument);
  EXPECT_THROW(read_protocol(file, std::numeric_limits<double>::infinity(), 0.1),
               std::invalid_argument);
  EXPECT_THROW(read_protocol(file, 2.0, 0.0), std::invalid_argument);
}

// ---- CSV histories ----

// Reference: protocol.hpp, CSV history (0.0 put first, legs subdivided in equal steps,
// cycles closed at each return from compression to non-negative deformation, a trailing
// incomplete cycle, amplitude = peak |deformation| in the cycle).
TEST(ProtocolCsv, HistoryIsReadSubdividedAndItsCyclesCounted) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("history.csv", "time,deformation,force\n"
                                                 "1.0,1.0,10\n"
                                                 "2.0,-1.0,-10\n"
                                                 "3.0,0.6,5\n"
                                                 "4.0,-0.3,-3\n"
                                                 "5.0,0,0\n"
                                                 "6.0,0.4,4\n");
  const LoadingProtocol protocol = read_protocol(file, 2.0, 0.5);
  EXPECT_EQ(protocol.name, file.string());
  expect_well_formed(protocol, 0.5);
  // 0 -> 1 in 2 steps, 1 -> -1 in 4, -1 -> 0.6 in 4 (of 0.4), 0.6 -> -0.3 in 2 (of 0.45),
  // -0.3 -> 0 in 1, 0 -> 0.4 in 1.
  const std::vector<double> expected{0.0,  0.5, 1.0, 0.5,  0.0,  -0.5, -1.0, -0.6,
                                     -0.2, 0.2, 0.6, 0.15, -0.3, 0.0,  0.4};
  ASSERT_EQ(protocol.deformation.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(protocol.deformation[i], expected[i], 1e-12) << "point " << i;
  }
  // Given points are kept exactly.
  EXPECT_EQ(protocol.deformation[2], 1.0);
  EXPECT_EQ(protocol.deformation[6], -1.0);
  EXPECT_EQ(protocol.deformation[10], 0.6);
  EXPECT_EQ(protocol.deformation[12], -0.3);
  EXPECT_EQ(protocol.deformation[13], 0.0);
  EXPECT_EQ(protocol.deformation[14], 0.4);
  // Cycle 1 closes at 0.2 (the first point >= 0 after -0.2), cycle 2 at the 0 after -0.3;
  // the final 0.4 starts an incomplete cycle 3.
  EXPECT_EQ(protocol.cycle, (std::vector<int>{0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 2, 2, 2, 2, 3}));
  EXPECT_EQ(protocol.cycle_amplitude, (std::vector<double>{1.0, 0.6, 0.4}));
}

// Reference: protocol.hpp (a history that starts at 0 keeps its first point; the cycles of
// a built-in protocol are counted back the same by the sign-reversal rule).
TEST(ProtocolCsv, BuiltinProtocolWrittenAsCsvReadsBackTheSame) {
  testing::ScratchDirectory scratch;
  const double dy = kUcsdG1YieldDeformation;
  const LoadingProtocol written = ucsd_protocol(dy, 0.25 * dy);
  NumericTable table({"step", "deformation"});
  for (std::size_t i = 0; i < written.deformation.size(); ++i) {
    const double row[] = {static_cast<double>(i), written.deformation[i]};
    table.append_row(row);
  }
  const auto file = scratch.write("ucsd.csv", table.text());
  const LoadingProtocol read = read_protocol(file, dy, 0.25 * dy);
  EXPECT_EQ(read.deformation, written.deformation);
  EXPECT_EQ(read.cycle, written.cycle);
  EXPECT_EQ(read.cycle_amplitude, written.cycle_amplitude);
}

// Reference: protocol.hpp (the leading direction is that of the first non-zero point: a
// compression-first cycle ends on the return from tension).
TEST(ProtocolCsv, CompressionFirstHistoryCountsCyclesFromTheLeadingDirection) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("history.csv", "deformation\n0\n-2\n2\n0\n-1\n");
  const LoadingProtocol protocol = read_protocol(file, 1.0, 1.0);
  EXPECT_EQ(protocol.deformation,
            (std::vector<double>{0.0, -1.0, -2.0, -1.0, 0.0, 1.0, 2.0, 1.0, 0.0, -1.0}));
  EXPECT_EQ(protocol.cycle, (std::vector<int>{0, 1, 1, 1, 1, 1, 1, 1, 1, 2}));
  EXPECT_EQ(protocol.cycle_amplitude, (std::vector<double>{2.0, 1.0}));
}

struct InvalidHistory {
  std::string name;
  std::string contents;
  std::string location; ///< where the error must point; empty: the whole file
};

void PrintTo(const InvalidHistory& invalid, std::ostream* out) {
  *out << invalid.name;
}

class ProtocolCsvRejects : public ::testing::TestWithParam<InvalidHistory> {};

// Reference: protocol.hpp CSV history and csv.hpp (errors name the file and the line).
TEST_P(ProtocolCsvRejects, WithFileAndLine) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("history.csv", GetParam().contents);
  try {
    read_protocol(file, 2.0, 0.1);
    FAIL() << GetParam().name << " was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), file.string());
    EXPECT_EQ(error.location(), GetParam().location);
    const std::string message = error.what();
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    EXPECT_FALSE(error.expected().empty());
  }
}

INSTANTIATE_TEST_SUITE_P(
    ProtocolEachInvalidHistory, ProtocolCsvRejects,
    ::testing::Values(
        InvalidHistory{"empty_file", "", ""},
        InvalidHistory{"no_data_rows", "step,deformation\n", ""},
        InvalidHistory{"missing_column", "step,strain\n1,0.5\n", "line 1 (header)"},
        InvalidHistory{"infinite_value", "deformation\n1\ninf\n", "line 3, column deformation"},
        InvalidHistory{"nan_value", "deformation\n1\nnan\n", "line 3, column deformation"},
        InvalidHistory{"not_a_number", "deformation\n1\nabc\n", "line 3, column deformation"},
        InvalidHistory{"empty_cell", "step,deformation\n1,\n", "line 2, column deformation"},
        InvalidHistory{"never_leaves_zero", "deformation\n0\n0\n", ""},
        InvalidHistory{"too_many_points", "deformation\n1e7\n", ""}),
    [](const ::testing::TestParamInfo<InvalidHistory>& info) { return info.param.name; });

// Reference: the example files of examples/protocols (they must stay valid) and
// BRB_SOURCE_FACTS sections 7 and 8 for the built-in ones.
TEST(ProtocolExamples, EveryExampleFileReads) {
  const std::filesystem::path folder = std::filesystem::path(BRB_SOURCE_DIR) / "examples/protocols";
  const double dy = kGironaD3YieldDeformation;
  const double default_max_step = 0.1;
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const auto extension = entry.path().extension();
    if (extension != ".json" && extension != ".csv")
      continue;
    ++files;
    SCOPED_TRACE(entry.path().string());
    const LoadingProtocol protocol = read_protocol(entry.path(), dy, default_max_step);
    EXPECT_GT(protocol.cycle_count(), 0u);
    EXPECT_EQ(protocol.cycle.size(), protocol.deformation.size());
  }
  EXPECT_GE(files, 2u);
  EXPECT_EQ(read_protocol(folder / "girona.json", dy, default_max_step).cycle_amplitude,
            girona_protocol(dy, 3, 0.05 * dy).cycle_amplitude);
  EXPECT_EQ(read_protocol(folder / "ucsd.json", dy, default_max_step).cycle_count(), 9u);
  // short_history.csv: 1.5, -1.5, 3, -3, 0 after an initial 0: two full cycles.
  EXPECT_EQ(read_protocol(folder / "short_history.csv", dy, default_max_step).cycle_amplitude,
            (std::vector<double>{1.5, 3.0}));
}

} // namespace
} // namespace brb::io
