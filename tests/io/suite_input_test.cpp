// Ground-motion suite files: the shipped suites and every rejected input.
#include "brb/io/suite_input.hpp"

#include "brb/io/input_error.hpp"

#include "io/scratch_directory.hpp"
#include "support/shared_records.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

namespace brb::io {
namespace {

using testing::ScratchDirectory;

std::filesystem::path suites() {
  return std::filesystem::path(BRB_SOURCE_DIR) / "frames" / "suites";
}

TEST(SuiteInput, Shared10HoldsTheTenSharedRecords) {
  const GroundMotionSuite suite = read_suite(suites() / "shared10.json");
  EXPECT_EQ(suite.name, "shared10");
  ASSERT_EQ(suite.records.size(), 10u);
  ASSERT_EQ(suite.motions.size(), 10u);
  std::vector<std::filesystem::path> files;
  for (const SuiteRecord& record : suite.records)
    files.push_back(std::filesystem::canonical(record.file));
  std::sort(files.begin(), files.end());
  std::vector<std::filesystem::path> shared;
  for (const auto& file : test::shared_at2_records())
    shared.push_back(std::filesystem::canonical(file));
  EXPECT_EQ(files, shared);
  // El Centro as read directly (units g from its header, no factor)
  for (std::size_t k = 0; k < suite.records.size(); ++k) {
    if (suite.records[k].name != "elCentro")
      continue;
    const GroundMotion direct = read_peer_at2(test::shared_ground_motions() / "elCentro.AT2");
    EXPECT_EQ(suite.motions[k].acceleration, direct.acceleration);
    EXPECT_EQ(suite.motions[k].dt, direct.dt);
  }
}

TEST(SuiteInput, FemaP695SetHasItsDtUnitsAndFactorsFromTheSharedTables) {
  const GroundMotionSuite suite = read_suite(suites() / "fema_p695_ff.json");
  ASSERT_EQ(suite.records.size(), 44u);
  // records.csv: file,event,station,component,dt_s,npts,units; eqData.dat: file dt factor
  const auto folder = test::shared_ground_motions() / "fema_p695_ff";
  std::ifstream table(folder / "records.csv");
  std::string line;
  std::getline(table, line);
  std::map<std::string, std::pair<double, std::size_t>> expected; // file -> (dt, npts)
  while (std::getline(table, line)) {
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');)
      cells.push_back(cell);
    expected[cells[0]] = {std::stod(cells[4]), std::stoul(cells[5])};
  }
  std::map<std::string, double> factors;
  std::ifstream data(folder / "eqData.dat");
  for (std::string file, dt, factor; data >> file >> dt >> factor;)
    factors[file] = std::stod(factor);
  for (std::size_t k = 0; k < suite.records.size(); ++k) {
    const std::string file = suite.records[k].file.filename().string();
    ASSERT_TRUE(expected.count(file)) << file;
    EXPECT_EQ(suite.motions[k].dt, expected[file].first) << file;
    EXPECT_EQ(suite.motions[k].acceleration.size(), expected[file].second) << file;
    EXPECT_EQ(suite.records[k].options.scale, factors[file]) << file;
    // the factor scales the record read in g
    const GroundMotion raw =
        read_acceleration_column(suite.records[k].file, AccelerationUnits::g, expected[file].first);
    EXPECT_DOUBLE_EQ(suite.motions[k].peak_acceleration(), factors[file] * raw.peak_acceleration())
        << file;
  }
}

struct BadSuite {
  std::string name;
  std::string json;    // "@SHARED@" stands for the shared ground-motion folder
  std::string message; // a part of the error
};

class SuiteRejected : public ::testing::TestWithParam<BadSuite> {};

TEST_P(SuiteRejected, WithAMessageNamingFileFieldAndExpectation) {
  const ScratchDirectory scratch;
  scratch.write("one.txt", "0.0\n0.1\n-0.1\n0.0\n");
  std::string text = GetParam().json;
  for (std::size_t at; (at = text.find("@SHARED@")) != std::string::npos;)
    text.replace(at, 8, test::shared_ground_motions().string());
  const auto file = scratch.write("suite.json", text);
  try {
    read_suite(file);
    FAIL() << "accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    EXPECT_NE(message.find(GetParam().message), std::string::npos) << message;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SuiteRejected,
    ::testing::Values(
        BadSuite{"NoRecords", R"({"records": []})", "/records: the suite needs at least one"},
        BadSuite{"RecordsMissing", R"({"name": "x"})", "/records"},
        BadSuite{"UnknownKey", R"({"records": [], "motions": []})", "motions"},
        BadSuite{"MissingFile", R"({"records": [{"file": "nowhere.AT2"}]})",
                 "/records/0/file: no such record file"},
        BadSuite{"UnknownUnits",
                 R"({"records": [{"file": "one.txt", "units": "gal", "dt": 0.01}]})",
                 "/records/0/units"},
        BadSuite{"ColumnWithoutDt", R"({"records": [{"file": "one.txt", "units": "g"}]})",
                 "states no time step: give dt"},
        BadSuite{"ColumnWithoutUnits", R"({"records": [{"file": "one.txt", "dt": 0.01}]})",
                 "/records/0"},
        BadSuite{"NegativeDt", R"({"records": [{"file": "one.txt", "units": "g", "dt": -0.01}]})",
                 "/records/0/dt: time step dt, s must be > 0"},
        BadSuite{"ZeroFactor",
                 R"({"records": [{"file": "one.txt", "units": "g", "dt": 0.01, "factor": 0}]})",
                 "/records/0/factor: normalisation factor must be > 0"},
        BadSuite{
            "UnknownDirection",
            R"({"records": [{"file": "one.txt", "units": "g", "dt": 0.01, "direction": "w"}]})",
            "/records/0/direction: the direction must be x, y or z"},
        BadSuite{"UnknownFormat",
                 R"({"records": [{"file": "one.txt", "units": "g", "dt": 0.01, "format": "xls"}]})",
                 "/records/0/format"},
        BadSuite{"DuplicateNames",
                 R"({"records": [{"file": "one.txt", "units": "g", "dt": 0.01},
                                 {"file": "one.txt", "units": "g", "dt": 0.02}]})",
                 "/records/1: duplicate record name \"one\""},
        BadSuite{"DuplicateGivenNames",
                 R"({"records": [{"file": "@SHARED@/elCentro.AT2", "name": "a"},
                                 {"file": "@SHARED@/ARL360.at2", "name": "a"}]})",
                 "duplicate record name \"a\""},
        BadSuite{"AtDtDisagrees", R"({"records": [{"file": "@SHARED@/elCentro.AT2", "dt": 0.01}]})",
                 "/records/0"}),
    [](const ::testing::TestParamInfo<BadSuite>& info) { return info.param.name; });

} // namespace
} // namespace brb::io
