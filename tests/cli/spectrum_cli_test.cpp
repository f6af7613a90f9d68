// `brb spectrum` end to end: the real binary (BRB_CLI_PATH) on the shared El Centro record.
#include "cli/run_brb.hpp"
#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>

#include <filesystem>
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

const std::filesystem::path kGroundMotions =
    std::filesystem::path(BRB_SHARED_DIR) / "data" / "ground_motions";

struct Spectrum {
  std::vector<double> periods;
  std::vector<double> sa_g;
};

Spectrum read_spectrum(const std::filesystem::path& file) {
  const auto lines = lines_of(read_file(file));
  Spectrum spectrum;
  EXPECT_FALSE(lines.empty());
  if (lines.empty())
    return spectrum;
  EXPECT_EQ(lines.front(), "period,Sa_g");
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto row = numbers_of(lines[i]);
    EXPECT_EQ(row.size(), 2u) << lines[i];
    if (row.size() == 2) {
      spectrum.periods.push_back(row[0]);
      spectrum.sa_g.push_back(row[1]);
    }
  }
  return spectrum;
}

TEST(SpectrumCli, ElCentroAtTheShortestPeriodIsItsPga) {
  ScratchDirectory scratch;
  const auto output = scratch.path() / "s.csv";
  const CliRun run =
      run_brb("spectrum " + shell_quoted((kGroundMotions / "elCentro.AT2").string()) +
              " --damping 0.05 --out " + shell_quoted(output.string()));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Spectrum spectrum = read_spectrum(output);
  ASSERT_EQ(spectrum.periods.size(), 301u); // 100 per decade, 0.01 s to 10 s
  EXPECT_EQ(spectrum.periods.front(), 0.01);
  EXPECT_EQ(spectrum.periods.back(), 10.0);
  for (std::size_t k = 1; k < spectrum.periods.size(); ++k)
    EXPECT_GT(spectrum.periods[k], spectrum.periods[k - 1]);
  // A 0.01 s oscillator is nearly rigid: Sa = PGA, 0.319 g in SOURCES.md, within 1 %.
  EXPECT_NEAR(spectrum.sa_g.front(), 0.319, 0.01 * 0.319);
  EXPECT_EQ(scratch.entries().size(), 1u); // no temporary file left
  EXPECT_NE(run.out.find("1559 points"), std::string::npos) << run.out;
}

TEST(SpectrumCli, ScaleMultipliesTheSpectrumExactly) {
  // The response is linear in the record; a factor 2 is exact in binary arithmetic.
  ScratchDirectory scratch;
  const std::string record = shell_quoted((kGroundMotions / "RIO270.AT2").string());
  const auto once = scratch.path() / "once.csv";
  const auto twice = scratch.path() / "twice.csv";
  ASSERT_EQ(run_brb("spectrum " + record + " --out " + shell_quoted(once.string())).exit_code, 0);
  ASSERT_EQ(
      run_brb("spectrum " + record + " --scale 2 --out " + shell_quoted(twice.string())).exit_code,
      0);
  const Spectrum a = read_spectrum(once);
  const Spectrum b = read_spectrum(twice);
  ASSERT_EQ(a.sa_g.size(), b.sa_g.size());
  for (std::size_t k = 0; k < a.sa_g.size(); ++k)
    EXPECT_EQ(b.sa_g[k], 2.0 * a.sa_g[k]) << "period " << a.periods[k];
}

TEST(SpectrumCli, ColumnRecordGivesTheSpectrumOfItsAt2Source) {
  // SOURCES.md: fema_p695_ff/34.rec is RIO270.AT2 (dt 0.02 s) to 5e-7 g; a linear response
  // to a difference of at most 5e-7 g stays far below 1e-4 g at every period.
  ScratchDirectory scratch;
  const auto from_at2 = scratch.path() / "at2.csv";
  const auto from_rec = scratch.path() / "rec.csv";
  ASSERT_EQ(run_brb("spectrum " + shell_quoted((kGroundMotions / "RIO270.AT2").string()) +
                    " --out " + shell_quoted(from_at2.string()))
                .exit_code,
            0);
  const CliRun rec =
      run_brb("spectrum " + shell_quoted((kGroundMotions / "fema_p695_ff" / "34.rec").string()) +
              " --units g --dt 0.02 --out " + shell_quoted(from_rec.string()));
  ASSERT_EQ(rec.exit_code, 0) << rec.err;
  const Spectrum a = read_spectrum(from_at2);
  const Spectrum b = read_spectrum(from_rec);
  ASSERT_EQ(a.sa_g.size(), b.sa_g.size());
  for (std::size_t k = 0; k < a.sa_g.size(); ++k)
    EXPECT_NEAR(b.sa_g[k], a.sa_g[k], 1e-4) << "period " << a.periods[k];
}

TEST(SpectrumCli, BadRecordExitsWithTwoNamingFileAndLine) {
  ScratchDirectory scratch;
  const auto record = scratch.write("bad.AT2", "PEER NGA STRONG MOTION DATABASE RECORD\n"
                                               "event\n"
                                               "ACCELERATION TIME SERIES IN UNITS OF G\n"
                                               "NPTS=  3, DT= .0100 SEC\n"
                                               " 0.1 0.2 zero\n");
  const auto output = scratch.path() / "s.csv";
  const CliRun run = run_brb("spectrum " + shell_quoted(record.string()) + " --out " +
                             shell_quoted(output.string()));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err.rfind("brb: error: " + record.string() + ": line 5: ", 0), 0u) << run.err;
  EXPECT_FALSE(std::filesystem::exists(output));

  const auto missing = scratch.path() / "absent.AT2";
  const CliRun absent = run_brb("spectrum " + shell_quoted(missing.string()) + " --out " +
                                shell_quoted(output.string()));
  EXPECT_EQ(absent.exit_code, 2);
  EXPECT_NE(absent.err.find(missing.string()), std::string::npos) << absent.err;
  EXPECT_EQ(scratch.entries().size(), 1u); // only bad.AT2
}

TEST(SpectrumCli, BadOptionsExitWithTwoNamingTheOption) {
  ScratchDirectory scratch;
  const std::string record = shell_quoted((kGroundMotions / "elCentro.AT2").string());
  const std::string out = " --out " + shell_quoted((scratch.path() / "s.csv").string());
  for (const std::string& options :
       {std::string("--units G"), std::string("--damping 1"), std::string("--dt 0.01"),
        std::string("--scale 0"), std::string("--format xyz")}) {
    const CliRun run = run_brb("spectrum " + record + " " + options + out);
    EXPECT_EQ(run.exit_code, 2) << options;
    const std::string option = options.substr(0, options.find(' '));
    const std::string named = option == "--dt" ? "dt" : option;
    EXPECT_NE(run.err.find(named), std::string::npos) << options << ": " << run.err;
  }
  EXPECT_TRUE(scratch.entries().empty());
}

} // namespace
