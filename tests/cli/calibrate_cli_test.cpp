// `brb calibrate` through the real binary: a synthetic record made by the fast axial model
// with known steel is fitted back (parameters file, protocol CSV mapping protocol points to
// record rows), and input errors exit with 2 naming the file and JSON path.
#include "brb/io/csv.hpp"
#include "brb/io/force_record.hpp"
#include "brb/validation/steel_calibration.hpp"
#include "cli/run_brb.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace brb::testing {
namespace {

constexpr const char* kBrace = R"({
  "name": "small", "units": "mm",
  "core": {"section": {"shape": "rectangle", "width": 40, "depth": 10},
           "steel": {"E": 200000, "nu": 0.3, "fy": 250, "H_kin": 0, "H_iso": 0},
           "yielding_length": 1000},
  "connection": {"length": 100, "section": {"shape": "rectangle", "width": 80, "depth": 20}}
})";

/// A record in kip and inch (deformation column first) made by the fast model of the brace
/// above with fy = 300 MPa and known hardening: cycles of 1, 3 and 6 dy.
std::string synthetic_record() {
  material::SteelParameters truth;
  truth.youngs_modulus = 200000;
  truth.yield_stress = 300;
  truth.chaboche = {{8000, 120}, {1000, 10}};
  truth.voce_saturation = 30;
  truth.voce_rate = 5;
  validation::AxialBraceIdealisation brace;
  brace.core_area = 400;
  brace.yielding_length = 1000;
  brace.youngs_modulus = 200000;
  brace.end_zone_flexibility = 2 * 100 / (200000.0 * 1600);
  const double dy = brace.yield_deformation(250);
  std::vector<double> deformation;
  double position = 0;
  for (const double amplitude : {1.0, 3.0, 6.0}) {
    for (const double target : {amplitude * dy, -amplitude * dy}) {
      for (int i = 1; i <= 40; ++i)
        deformation.push_back(position + (target - position) * i / 40);
      position = target;
    }
  }
  const std::vector<double> force = validation::fast_brace_forces(truth, brace, deformation);
  std::string text = "Deformation[in],Force[kip]\n";
  for (std::size_t i = 0; i < force.size(); ++i) {
    text += io::format_number(deformation[i] / 25.4) + "," +
            io::format_number(force[i] / 4448.2216152605) + "\n";
  }
  return text;
}

TEST(CalibrateCli, FitsASyntheticRecordAndWritesParametersAndProtocol) {
  ScratchDirectory scratch;
  const auto brace = scratch.write("brace.json", kBrace);
  scratch.write("record.csv", synthetic_record());
  const auto reference = scratch.write("record.json", R"({"reference": {"file": "record.csv",
      "columns": {"force": "Force[kip]", "deformation": "Deformation[in]"},
      "units": {"force": "kip", "length": "in"}}})");
  const auto params = scratch.path() / "params.json";
  const auto protocol = scratch.path() / "protocol.csv";
  const CliRun run =
      run_brb("calibrate " + shell_quoted(brace.string()) + " --record " +
              shell_quoted(reference.string()) + " --out " + shell_quoted(params.string()) +
              " --protocol-out " + shell_quoted(protocol.string()) + " --side all");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto result = nlohmann::json::parse(read_file(params));
  EXPECT_LT(result["calibration"]["normalised_rms_error"].get<double>(), 0.01);
  EXPECT_GT(result["calibration"]["start_error"].get<double>(), 0.05);
  EXPECT_NEAR(result["steel"]["fy"].get<double>(), 300.0, 30.0);
  EXPECT_EQ(result["steel"]["chaboche"].size(), 2u);

  // Every protocol point that names a record row has the record's deformation there.
  const auto rows = io::read_numeric_column(protocol, "record_row");
  const auto points = io::read_numeric_column(protocol, "deformation");
  io::ForceRecordFormat format{"Force[kip]", "Deformation[in]", "kip", "in", {}};
  const io::ForceRecord record = io::read_force_record(scratch.path() / "record.csv", format);
  EXPECT_EQ(points.values.front(), 0.0);
  EXPECT_EQ(rows.values.front(), -1.0);
  for (std::size_t k = 1; k < rows.values.size(); ++k) {
    if (rows.values[k] >= 0) {
      EXPECT_EQ(points.values[k], record.deformation[static_cast<std::size_t>(rows.values[k])]);
    }
  }
}

TEST(CalibrateCli, TakesAMetricsReferenceWithItsTypeAndStatedFailure) {
  // A validation metrics.json's reference as brb validate reads it: "type" and "failure" are
  // part of the schema (validation/README.md), not unknown keys.
  ScratchDirectory scratch;
  const auto brace = scratch.write("brace.json", kBrace);
  scratch.write("record.csv", synthetic_record());
  const auto reference = scratch.write("metrics.json", R"({"reference": {"type": "lab_record",
      "file": "record.csv", "failure": {"failure_mode": "none"},
      "columns": {"force": "Force[kip]", "deformation": "Deformation[in]"},
      "units": {"force": "kip", "length": "in"}}})");
  const auto params = scratch.path() / "params.json";
  const CliRun run =
      run_brb("calibrate " + shell_quoted(brace.string()) + " --record " +
              shell_quoted(reference.string()) + " --out " + shell_quoted(params.string()));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(std::filesystem::exists(params));

  const auto unknown = scratch.write("unknown.json", R"({"reference": {"type": "abaqus_odb",
      "file": "record.csv"}})");
  const CliRun refused =
      run_brb("calibrate " + shell_quoted(brace.string()) + " --record " +
              shell_quoted(unknown.string()) + " --out " + shell_quoted(params.string()));
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("/reference/type"), std::string::npos) << refused.err;
}

TEST(CalibrateCli, RejectsABadRecordReferenceWithExitTwoAndWritesNothing) {
  ScratchDirectory scratch;
  const auto brace = scratch.write("brace.json", kBrace);
  const auto reference = scratch.write("record.json", R"({"reference": {"file": "record.csv",
      "columns": {"force": "F", "deformation": "D"}, "units": {"force": "lbs", "length": "in"}}})");
  const auto params = scratch.path() / "params.json";
  const CliRun run =
      run_brb("calibrate " + shell_quoted(brace.string()) + " --record " +
              shell_quoted(reference.string()) + " --out " + shell_quoted(params.string()));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("/reference/units/force"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(params));
}

} // namespace
} // namespace brb::testing
