// `brb material` end to end: the real binary (BRB_CLI_PATH) run on temporary files.
#include "cli/run_brb.hpp"
#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <string>
#include <vector>

namespace {

using brb::testing::CliRun;
using brb::testing::lines_of;
using brb::testing::numbers_of;
using brb::testing::read_file;
using brb::testing::run_brb;
using brb::testing::ScratchDirectory;
using brb::testing::shell_quoted;

std::string material_arguments(const std::string& law, const std::filesystem::path& parameters,
                               const std::filesystem::path& history,
                               const std::filesystem::path& output) {
  return "material --law " + law + " --params " + shell_quoted(parameters.string()) + " --strain " +
         shell_quoted(history.string()) + " --out " + shell_quoted(output.string());
}

std::string shortest(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

// S275-like steel (illustrative Chaboche + Voce hardening), no damage.
constexpr double kSteelModulus = 210000.0;
constexpr double kSteelYield = 275.0;
const char* const kSteelParameters = R"(// test steel
{"E": 210000, "nu": 0.3, "fy": 275, "H_kin": 0, "H_iso": 0,
 "chaboche": [{"C": 6000, "gamma": 60}, {"C": 1500, "gamma": 8}],
 "voce": {"Q": 40, "b": 10}, "units": "MPa"})";

// The small-BRB mortar of the source.
constexpr double kMortarModulus = 17520.0;
constexpr double kMortarTensileStrength = 3.992;
const char* const kMortarParameters =
    R"({"E": 17520, "nu": 0.2, "fc": 39.92, "ft": 3.992, "Gf": 0.75, "lc": 50})";

TEST(BrbCli, HelpWorks) {
  const CliRun top = run_brb("--help");
  EXPECT_EQ(top.exit_code, 0) << top.err;
  EXPECT_NE(top.out.find("material"), std::string::npos) << top.out;

  const CliRun material = run_brb("material --help");
  EXPECT_EQ(material.exit_code, 0) << material.err;
  for (const char* word :
       {"--law", "--params", "--strain", "--out", "steel3d-collapsed", "mortar3d-collapsed"}) {
    EXPECT_NE(material.out.find(word), std::string::npos) << word << " not in:\n" << material.out;
  }
}

TEST(BrbCli, UsageErrorsExitWithTwo) {
  EXPECT_EQ(run_brb("").exit_code, 2);
  EXPECT_EQ(run_brb("no-such-command").exit_code, 2);
  const CliRun missing_out = run_brb("material --law steel --params p.json --strain h.csv");
  EXPECT_EQ(missing_out.exit_code, 2);
  EXPECT_NE(missing_out.err.find("--out"), std::string::npos) << missing_out.err;
  const CliRun bad_law =
      run_brb("material --law bronze --params p.json --strain h.csv --out o.csv");
  EXPECT_EQ(bad_law.exit_code, 2);
  EXPECT_NE(bad_law.err.find("--law"), std::string::npos) << bad_law.err;
}

class SteelRun : public ::testing::TestWithParam<std::string> {};

TEST_P(SteelRun, WritesOneRowPerStrainAndFollowsHookeInTheElasticRange) {
  ScratchDirectory scratch;
  const auto parameters = scratch.write("p.json", kSteelParameters);
  // Elastic loading to 0.9 eps_y and back, then plastic excursions to +-3 eps_y.
  const double yield_strain = kSteelYield / kSteelModulus;
  std::vector<double> strains;
  for (int k = 1; k <= 9; ++k)
    strains.push_back(0.1 * k * yield_strain);
  for (int k = 8; k >= -9; --k)
    strains.push_back(0.1 * k * yield_strain);
  const std::size_t elastic_rows = strains.size();
  for (int k = 1; k <= 30; ++k)
    strains.push_back(0.1 * k * yield_strain);
  for (int k = 29; k >= -30; --k)
    strains.push_back(0.1 * k * yield_strain);
  std::string history = "step,strain,note\n";
  for (std::size_t i = 0; i < strains.size(); ++i) {
    history += std::to_string(i + 1) + "," + shortest(strains[i]) + ",x\n";
  }
  const auto history_file = scratch.write("history.csv", history);
  const auto output = scratch.path() / "out.csv";

  const CliRun run = run_brb(material_arguments(GetParam(), parameters, history_file, output));
  ASSERT_EQ(run.exit_code, 0) << run.err;

  const auto lines = lines_of(read_file(output));
  ASSERT_EQ(lines.size(), strains.size() + 1);
  EXPECT_EQ(lines.front(), "strain,stress,tangent,damage");
  double largest_stress = 0.0;
  double smallest_stress = 0.0;
  for (std::size_t i = 0; i < strains.size(); ++i) {
    const auto row = numbers_of(lines[i + 1]);
    ASSERT_EQ(row.size(), 4u) << lines[i + 1];
    EXPECT_EQ(row[0], strains[i]); // the imposed strain, at full precision
    EXPECT_EQ(row[3], 0.0);        // no Gf: no damage
    if (i < elastic_rows) {
      const double hooke = kSteelModulus * strains[i]; // sigma = E eps
      EXPECT_NEAR(row[1], hooke, 1e-9 * kSteelYield) << "row " << i + 1;
      EXPECT_NEAR(row[2], kSteelModulus, 1e-7 * kSteelModulus) << "row " << i + 1;
    }
    largest_stress = std::max(largest_stress, row[1]);
    smallest_stress = std::min(smallest_stress, row[1]);
  }
  // Past yield with only hardening terms, the stress goes beyond fy both ways.
  EXPECT_GT(largest_stress, kSteelYield);
  EXPECT_LT(smallest_stress, -kSteelYield);
  EXPECT_EQ(scratch.entries().size(), 3u); // p.json, history.csv, out.csv: no temporary left
}

INSTANTIATE_TEST_SUITE_P(BothEvaluations, SteelRun, ::testing::Values("steel", "steel3d-collapsed"),
                         [](const auto& info) {
                           return info.param == "steel" ? std::string("ClosedForm")
                                                        : std::string("Collapsed3D");
                         });

class MortarRun : public ::testing::TestWithParam<std::string> {};

TEST_P(MortarRun, IsElasticUpToTheTensileStrengthThenDamages) {
  ScratchDirectory scratch;
  const auto parameters = scratch.write("mortar.json", kMortarParameters);
  const double cracking_strain = kMortarTensileStrength / kMortarModulus;
  const std::vector<double> strains{0.25 * cracking_strain, 0.5 * cracking_strain,
                                    0.99 * cracking_strain, 3.0 * cracking_strain};
  std::string history = "strain\n";
  for (const double strain : strains)
    history += shortest(strain) + "\n";
  const auto output = scratch.path() / "out.csv";
  const CliRun run =
      run_brb(material_arguments(GetParam(), parameters, scratch.write("h.csv", history), output));
  ASSERT_EQ(run.exit_code, 0) << run.err;

  const auto lines = lines_of(read_file(output));
  ASSERT_EQ(lines.size(), strains.size() + 1);
  EXPECT_EQ(lines.front(), "strain,stress,tangent,damage");
  for (std::size_t i = 0; i < 3; ++i) {
    const auto row = numbers_of(lines[i + 1]);
    EXPECT_NEAR(row[1], kMortarModulus * strains[i], 1e-9 * kMortarTensileStrength);
    EXPECT_EQ(row[3], 0.0);
  }
  const auto cracked = numbers_of(lines.back());
  EXPECT_GT(cracked[3], 0.0);
  EXPECT_LT(cracked[1], kMortarTensileStrength);
}

INSTANTIATE_TEST_SUITE_P(BothEvaluations, MortarRun,
                         ::testing::Values("mortar", "mortar3d-collapsed"), [](const auto& info) {
                           return info.param == "mortar" ? std::string("ClosedForm")
                                                         : std::string("Collapsed3D");
                         });

struct BadInput {
  std::string name;
  std::string law;
  std::string parameters;
  std::string history;
  std::string file;  ///< the file the message must name: "params" or "history"
  std::string where; ///< JSON path or CSV line the message must name
};

void PrintTo(const BadInput& bad, std::ostream* out) {
  *out << bad.name;
}

const std::string kGoodHistory = "strain\n0.0001\n0.0002\n";

class RejectedInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(RejectedInput, ExitsWithTwoNamesFileAndPlaceAndWritesNothing) {
  const BadInput& bad = GetParam();
  ScratchDirectory scratch;
  const auto parameters = scratch.write("p.json", bad.parameters);
  const auto history = scratch.write("history.csv", bad.history);
  const auto output = scratch.path() / "out.csv";

  const CliRun run = run_brb(material_arguments(bad.law, parameters, history, output));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  const std::string named = (bad.file == "params" ? parameters : history).string();
  EXPECT_EQ(run.err.rfind("brb: error: " + named + ": " + bad.where, 0), 0u) << run.err;
  EXPECT_FALSE(std::filesystem::exists(output));
  EXPECT_EQ(scratch.entries().size(), 2u); // only the inputs
}

INSTANTIATE_TEST_SUITE_P(
    EachKind, RejectedInput,
    ::testing::Values(
        BadInput{"negative_fy", "steel",
                 R"({"E": 210000, "nu": 0.3, "fy": -5, "H_kin": 0, "H_iso": 0})", kGoodHistory,
                 "params", "/fy: "},
        BadInput{"unknown_key", "steel3d-collapsed",
                 R"({"E": 210000, "nu": 0.3, "fy": 275, "H_kin": 0, "H_iso": 0, "Hkin": 1})",
                 kGoodHistory, "params", "/Hkin: "},
        BadInput{"missing_key", "steel", R"({"E": 210000, "nu": 0.3, "fy": 275, "H_kin": 0})",
                 kGoodHistory, "params", "/H_iso: "},
        BadInput{"lc_too_long", "steel",
                 R"({"E": 210000, "nu": 0.3, "fy": 275, "H_kin": 0, "H_iso": 0,
                     "fu": 430, "Gf": 60, "lc": 1000})",
                 kGoodHistory, "params", "/lc: "},
        BadInput{"mortar_fc_below_ft", "mortar",
                 R"({"E": 17520, "nu": 0.2, "fc": 1, "ft": 3.992, "Gf": 0.75, "lc": 50})",
                 kGoodHistory, "params", "/fc: "},
        BadInput{"mortar_given_steel", "mortar3d-collapsed",
                 R"({"E": 210000, "nu": 0.3, "fy": 275, "H_kin": 0, "H_iso": 0})", kGoodHistory,
                 "params", "/"},
        BadInput{"missing_strain_column", "steel",
                 R"({"E": 210000, "nu": 0.3, "fy": 275, "H_kin": 0, "H_iso": 0})", "eps\n0.001\n",
                 "history", "line 1"},
        BadInput{"non_numeric_strain", "steel",
                 R"({"E": 210000, "nu": 0.3, "fy": 275, "H_kin": 0, "H_iso": 0})",
                 "strain\n0.001\n1e-3.5\n", "history", "line 3, column strain: "},
        BadInput{"empty_history", "steel",
                 R"({"E": 210000, "nu": 0.3, "fy": 275, "H_kin": 0, "H_iso": 0})", "", "history",
                 ""}),
    [](const ::testing::TestParamInfo<BadInput>& info) { return info.param.name; });

TEST(BrbCli, FailedRunLeavesAPreviousOutputUntouched) {
  ScratchDirectory scratch;
  const auto parameters = scratch.write("p.json", kSteelParameters);
  const auto history = scratch.write("history.csv", "strain\n0.001\nnan\n");
  const auto output = scratch.write("out.csv", "previous results\n");
  const CliRun run = run_brb(material_arguments("steel", parameters, history, output));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(read_file(output), "previous results\n");
  EXPECT_EQ(scratch.entries().size(), 3u);
}

TEST(BrbCli, IncrementThatCannotBeFollowedFailsNamingTheLine) {
  // 1e300 is far beyond anything the collapsed law's local Newton can reach with finite
  // numbers, whatever the substepping: the run must fail on that row and write nothing.
  ScratchDirectory scratch;
  const auto parameters = scratch.write("p.json", kSteelParameters);
  const auto history = scratch.write("history.csv", "strain\n0.001\n1e300\n");
  const auto output = scratch.path() / "out.csv";
  const CliRun run = run_brb(material_arguments("steel3d-collapsed", parameters, history, output));
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(run.err.rfind("brb: error: " + history.string() + ": line 3: ", 0), 0u) << run.err;
  EXPECT_FALSE(std::filesystem::exists(output));
  EXPECT_EQ(scratch.entries().size(), 2u);
}

TEST(BrbCli, MissingOutputDirectoryIsAnInputError) {
  ScratchDirectory scratch;
  const auto parameters = scratch.write("p.json", kSteelParameters);
  const auto history = scratch.write("history.csv", kGoodHistory);
  const auto output = scratch.path() / "no-such-directory" / "out.csv";
  const CliRun run = run_brb(material_arguments("steel", parameters, history, output));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(output.string()), std::string::npos) << run.err;
  EXPECT_EQ(scratch.entries().size(), 2u);
}

TEST(BrbCli, MissingParameterFileIsNamed) {
  ScratchDirectory scratch;
  const auto history = scratch.write("history.csv", kGoodHistory);
  const auto parameters = scratch.path() / "absent.json";
  const CliRun run =
      run_brb(material_arguments("steel", parameters, history, scratch.path() / "out.csv"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(parameters.string()), std::string::npos) << run.err;
}

} // namespace
