// Ground-motion readers: the ten shared PEER AT2 files (NPTS, DT and PGA against
// shared/data/SOURCES.md), the header and layout variants written to temporary files, CSV and
// single-column records, and every input error (file, line and what was expected).
#include "brb/io/ground_motion.hpp"
#include "brb/io/input_error.hpp"
#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace brb::io {
namespace {

const std::filesystem::path kGroundMotions =
    std::filesystem::path(BRB_SHARED_DIR) / "data" / "ground_motions";

/// A record as SOURCES.md lists it: NPTS, DT (s) and PGA (g, three digits).
struct SharedRecord {
  std::string file;
  std::size_t npts;
  double dt;
  double pga_g;
};

void PrintTo(const SharedRecord& record, std::ostream* out) {
  *out << record.file;
}

class SharedAt2File : public ::testing::TestWithParam<SharedRecord> {};

TEST_P(SharedAt2File, HasTheCountTimeStepAndPeakThatSourcesListsInMillimetres) {
  const SharedRecord& expected = GetParam();
  const GroundMotion motion = read_peer_at2(kGroundMotions / expected.file);
  EXPECT_EQ(motion.acceleration.size(), expected.npts);
  EXPECT_EQ(motion.dt, expected.dt); // ".02000" and 0.02 are the same double
  // SOURCES.md gives the PGA to three digits: within half a unit of the third.
  EXPECT_NEAR(motion.peak_acceleration() / kStandardGravity, expected.pga_g, 0.0005);
  EXPECT_EQ(motion.name, std::filesystem::path(expected.file).stem().string());

  // The same file through the format chosen from its extension (.AT2 or .at2).
  const GroundMotion loaded = load_ground_motion(kGroundMotions / expected.file);
  EXPECT_EQ(loaded.acceleration, motion.acceleration);
}

INSTANTIATE_TEST_SUITE_P(
    SourcesMd, SharedAt2File,
    ::testing::Values(SharedRecord{"elCentro.AT2", 1559, 0.02, 0.319},
                      SharedRecord{"RSN6_IMPVALL.I_I-ELC180.AT2", 5372, 0.01, 0.281},
                      SharedRecord{"RSN77_SFERN_PUL164.AT2", 4172, 0.01, 1.219},
                      SharedRecord{"Rinaldi228.AT2", 1991, 0.01, 0.874},
                      SharedRecord{"ARL360.at2", 2000, 0.02, 0.308},
                      SharedRecord{"TAK000.AT2", 4096, 0.01, 0.618},
                      SharedRecord{"RSN753_LOMAP_CLS000.AT2", 7995, 0.005, 0.645},
                      SharedRecord{"RSN879_LANDERS_LCN260.AT2", 9625, 0.005, 0.725},
                      SharedRecord{"TCU052-N.AT2", 18000, 0.005, 0.419},
                      SharedRecord{"RIO270.AT2", 1800, 0.02, 0.385}),
    [](const ::testing::TestParamInfo<SharedRecord>& info) {
      std::string name = std::filesystem::path(info.param.file).stem().string();
      for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c)))
          c = '_';
      }
      return name;
    });

TEST(PeerAt2, ConvertsGToMillimetresThenScales) {
  // elCentro.AT2's first values: 0.00630 0.00364 (g).
  const auto file = kGroundMotions / "elCentro.AT2";
  const GroundMotion motion = read_peer_at2(file);
  EXPECT_DOUBLE_EQ(motion.acceleration[0], 0.00630 * 9806.65);
  EXPECT_DOUBLE_EQ(motion.acceleration[1], 0.00364 * 9806.65);
  const GroundMotion scaled = read_peer_at2(file, std::nullopt, 2.5);
  EXPECT_DOUBLE_EQ(scaled.acceleration[1], 2.5 * 0.00364 * 9806.65);
  // An override replaces the header's units.
  const GroundMotion metres = read_peer_at2(file, AccelerationUnits::m_per_s2);
  EXPECT_DOUBLE_EQ(metres.acceleration[1], 0.00364 * 1000.0);
}

const char* const kNgaHeader = "PEER NGA STRONG MOTION DATABASE RECORD\n"
                               "Test, 1/1/2000, Station, 090\n"
                               "ACCELERATION TIME SERIES IN UNITS OF G\n";

TEST(PeerAt2, ReadsCrlfAndBlankLinesAndIgnoresTextAfterDt) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.write(
      "crlf.AT2", "PEER NGA STRONG MOTION DATABASE RECORD\r\n"
                  "Test, 1/1/2000, Station, 090\r\r\n"
                  "ACCELERATION TIME SERIES IN UNITS OF G\r\n"
                  "NPTS=      7, DT=   .0050 SEC,   0 POLE @    30.00000 HZ,  -5 POLE @  .05\r\n"
                  "   .1000000E-01  -.2000000E-01   .3000000E-01\r\n"
                  "\r\n"
                  "  -.4000000E-01   .5000000E-01  -.6000000E-01\r\r\n"
                  "   .7000000E-01                              \r\n"
                  "   \r\n");
  const GroundMotion motion = read_peer_at2(file);
  EXPECT_EQ(motion.dt, 0.005);
  const std::vector<double> g{0.01, -0.02, 0.03, -0.04, 0.05, -0.06, 0.07};
  ASSERT_EQ(motion.acceleration.size(), g.size());
  for (std::size_t i = 0; i < g.size(); ++i)
    EXPECT_DOUBLE_EQ(motion.acceleration[i], g[i] * kStandardGravity);
}

TEST(PeerAt2, SplitsTouchingNumbersByTheFieldWidthOfTheHeadersFortranFormat) {
  // 8F10.7: a negative number fills its 10 columns and touches the previous one.
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("touching.AT2", "Test record\n"
                                                  "listed in the format 8F10.7\n"
                                                  "The units are (g)\n"
                                                  "NPTS=  5, DT= .01000 SEC\n"
                                                  "-0.1234567-0.2345678 0.3456789\n"
                                                  " 0.0000001-0.9999999\n");
  const GroundMotion motion = read_peer_at2(file);
  const std::vector<double> g{-0.1234567, -0.2345678, 0.3456789, 0.0000001, -0.9999999};
  ASSERT_EQ(motion.acceleration.size(), g.size());
  for (std::size_t i = 0; i < g.size(); ++i)
    EXPECT_DOUBLE_EQ(motion.acceleration[i], g[i] * kStandardGravity);
}

TEST(PeerAt2, SplitsTouchingNumbersInTenColumnsWhenTheHeaderNamesNoFormat) {
  testing::ScratchDirectory scratch;
  const auto file =
      scratch.write("touching.at2", std::string(kNgaHeader) + "NPTS=  4, DT= .02 SEC\n"
                                                              "-123.45678-234.56789   0.00100\n"
                                                              "   0.00200\n");
  const GroundMotion motion = read_peer_at2(file);
  const std::vector<double> g{-123.45678, -234.56789, 0.001, 0.002};
  ASSERT_EQ(motion.acceleration.size(), g.size());
  for (std::size_t i = 0; i < g.size(); ++i)
    EXPECT_DOUBLE_EQ(motion.acceleration[i], g[i] * kStandardGravity);
}

struct BadAt2 {
  std::string name;
  std::string text;
  std::string location;           ///< where the message must point ("" for the whole file)
  std::vector<std::string> words; ///< what the message must say
};

void PrintTo(const BadAt2& bad, std::ostream* out) {
  *out << bad.name;
}

class RejectedAt2 : public ::testing::TestWithParam<BadAt2> {};

TEST_P(RejectedAt2, NamesTheFileTheLineAndWhatWasExpected) {
  const BadAt2& bad = GetParam();
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("bad.AT2", bad.text);
  try {
    read_peer_at2(file);
    FAIL() << "no error for " << bad.name;
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), file.string());
    EXPECT_EQ(error.location(), bad.location) << error.what();
    for (const std::string& word : bad.words)
      EXPECT_NE(std::string(error.what()).find(word), std::string::npos) << error.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    EachKind, RejectedAt2,
    ::testing::Values(
        BadAt2{"non_numeric_value",
               std::string(kNgaHeader) + "NPTS= 3, DT= .01 SEC\n 0.1 0.2\n 0.x\n",
               "line 6",
               {"0.x"}},
        BadAt2{"npts_larger_than_count",
               std::string(kNgaHeader) + "NPTS= 4, DT= .01 SEC\n 0.1 0.2 0.3\n",
               "line 4",
               {"NPTS=4", "3 values"}},
        BadAt2{"npts_smaller_than_count",
               std::string(kNgaHeader) + "NPTS= 2, DT= .01 SEC\n 0.1 0.2 0.3\n",
               "line 4",
               {"NPTS=2", "3 values"}},
        BadAt2{"empty_record",
               std::string(kNgaHeader) + "NPTS= 3, DT= .01 SEC\n\n",
               "line 4",
               {"empty record"}},
        BadAt2{"zero_dt",
               std::string(kNgaHeader) + "NPTS= 1, DT= 0.0 SEC\n 0.1\n",
               "line 4",
               {"DT > 0"}},
        BadAt2{"negative_dt",
               std::string(kNgaHeader) + "NPTS= 1, DT= -.01 SEC\n 0.1\n",
               "line 4",
               {"DT > 0"}},
        BadAt2{"missing_dt", std::string(kNgaHeader) + "NPTS= 1\n 0.1\n", "line 4", {"DT="}},
        BadAt2{"bad_npts",
               std::string(kNgaHeader) + "NPTS= 1.5, DT= .01 SEC\n 0.1\n",
               "line 4",
               {"NPTS="}},
        BadAt2{"no_npts_line", "0.1 0.2\n0.3\n", "", {"NPTS"}},
        BadAt2{"empty_file", "", "", {"empty"}},
        BadAt2{
            "no_units", "title\nevent\nno unit here\nNPTS= 1, DT= .01 SEC\n 0.1\n", "", {"units"}},
        BadAt2{"unsupported_units",
               "title\nevent\nACCELERATION IN UNITS OF CM/SEC/SEC\nNPTS= 1, DT= .01 SEC\n 0.1\n",
               "line 3",
               {"CM/SEC/SEC", "g, m/s^2 or mm/s^2"}},
        BadAt2{"velocity_record",
               "PEER NGA STRONG MOTION DATABASE RECORD\nevent\nVELOCITY TIME SERIES IN UNITS OF "
               "CM/S\nNPTS= 1, DT= .01 SEC\n 0.1\n",
               "line 3",
               {"acceleration record"}}),
    [](const ::testing::TestParamInfo<BadAt2>& info) { return info.param.name; });

TEST(PeerAt2, MissingFileIsNamed) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.path() / "absent.AT2";
  try {
    read_peer_at2(file);
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), file.string());
    EXPECT_NE(error.expected().find("does not exist"), std::string::npos) << error.what();
  }
}

TEST(PeerAt2, UnitsOverrideAcceptsAHeaderWithoutUnitsAndScaleMustBeNonZero) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("bare.AT2", "title\nevent\nno unit here\nNPTS= 2, DT= .01 SEC\n"
                                              " 0.5 -0.25\n");
  const GroundMotion motion = read_peer_at2(file, AccelerationUnits::m_per_s2);
  EXPECT_EQ(motion.acceleration, (std::vector<double>{500.0, -250.0}));
  EXPECT_THROW(read_peer_at2(file, AccelerationUnits::g, 0.0), InputError);
  EXPECT_THROW(read_peer_at2(file, AccelerationUnits::g, std::nan("")), InputError);
}

TEST(AccelerationUnits, ParsesTheThreeNamesAndNamesTheFieldOtherwise) {
  EXPECT_EQ(parse_acceleration_units("g", "f", "--units"), AccelerationUnits::g);
  EXPECT_EQ(parse_acceleration_units("m/s^2", "f", "--units"), AccelerationUnits::m_per_s2);
  EXPECT_EQ(parse_acceleration_units("mm/s^2", "f", "--units"), AccelerationUnits::mm_per_s2);
  EXPECT_EQ(millimetres_per_s2(AccelerationUnits::g), 9806.65);
  EXPECT_EQ(millimetres_per_s2(AccelerationUnits::m_per_s2), 1000.0);
  EXPECT_EQ(millimetres_per_s2(AccelerationUnits::mm_per_s2), 1.0);
  try {
    parse_acceleration_units("G", "suite.json", "/motions/0/units");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "suite.json");
    EXPECT_EQ(error.location(), "/motions/0/units");
    EXPECT_NE(error.expected().find("\"G\""), std::string::npos) << error.what();
  }
}

TEST(AccelerationCsv, TimeAndAccelColumnsGiveTheTimeStep) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("m.csv", "# a record\ntime,accel,note\n0.0,0.1,a\n0.01,-0.2,b\n"
                                           "0.02,0.3,c\n0.03,0.0,d\n");
  const GroundMotion motion = read_acceleration_csv(file, AccelerationUnits::g);
  EXPECT_DOUBLE_EQ(motion.dt, 0.01);
  ASSERT_EQ(motion.acceleration.size(), 4u);
  EXPECT_DOUBLE_EQ(motion.acceleration[1], -0.2 * kStandardGravity);
  EXPECT_EQ(motion.name, "m");
  // A given dt that agrees is accepted; one that does not is an error naming both.
  EXPECT_NO_THROW(read_acceleration_csv(file, AccelerationUnits::g, 0.01));
  try {
    read_acceleration_csv(file, AccelerationUnits::g, 0.02);
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "dt");
    EXPECT_NE(error.expected().find("0.02 s"), std::string::npos) << error.what();
    EXPECT_NE(error.expected().find("0.01 s"), std::string::npos) << error.what();
  }
}

TEST(AccelerationCsv, NonUniformTimesAreAnErrorAtTheirLine) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("m.csv", "time,accel\n0,0\n0.01,1\n0.025,2\n0.03,3\n");
  try {
    read_acceleration_csv(file, AccelerationUnits::g);
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "line 4, column time") << error.what();
  }
}

TEST(AccelerationCsv, SingleColumnWithOrWithoutHeaderNeedsTheTimeStep) {
  testing::ScratchDirectory scratch;
  const auto headed = scratch.write("headed.csv", "accel\n1.5\n-2\n");
  const auto bare = scratch.write("bare.csv", "1.5\r\n-2\r\n\r\n");
  for (const auto& file : {headed, bare}) {
    const GroundMotion motion = read_acceleration_csv(file, AccelerationUnits::mm_per_s2, 0.005);
    EXPECT_EQ(motion.dt, 0.005);
    EXPECT_EQ(motion.acceleration, (std::vector<double>{1.5, -2.0})) << file;
    try {
      read_acceleration_csv(file, AccelerationUnits::g);
      FAIL() << "no error without dt for " << file;
    } catch (const InputError& error) {
      EXPECT_EQ(error.location(), "dt") << error.what();
    }
  }
}

TEST(AccelerationCsv, ErrorsNameFileLineAndColumn) {
  testing::ScratchDirectory scratch;
  const auto non_numeric = scratch.write("a.csv", "time,accel\n0,1\n0.01,abc\n");
  try {
    read_acceleration_csv(non_numeric, AccelerationUnits::g);
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), non_numeric.string());
    EXPECT_EQ(error.location(), "line 3, column accel") << error.what();
  }
  const auto bare_bad = scratch.write("b.csv", "0.1\n0.2\nx1\n");
  try {
    read_acceleration_csv(bare_bad, AccelerationUnits::g, 0.01);
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "line 3") << error.what();
  }
  const auto empty = scratch.write("c.csv", "# nothing\n\n");
  EXPECT_THROW(read_acceleration_csv(empty, AccelerationUnits::g, 0.01), InputError);
  const auto header_only = scratch.write("d.csv", "time,accel\n");
  EXPECT_THROW(read_acceleration_csv(header_only, AccelerationUnits::g), InputError);
  const auto wrong_column = scratch.write("e.csv", "acc\n0.1\n");
  try {
    read_acceleration_csv(wrong_column, AccelerationUnits::g, 0.01);
    FAIL();
  } catch (const InputError& error) {
    EXPECT_NE(error.expected().find("'accel'"), std::string::npos) << error.what();
  }
  const auto headed = scratch.write("f.csv", "accel\n0.1\n");
  try {
    read_acceleration_csv(headed, AccelerationUnits::g, -0.01);
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "dt") << error.what();
  }
}

TEST(AccelerationColumn, ReadsAFemaP695RecordWithTheGivenTimeStep) {
  // 0.rec: 3000 values (records.csv, npts counted from the file), the first two 0.0 and
  // 3.49305e-05 (g, inferred in SOURCES.md).
  const auto file = kGroundMotions / "fema_p695_ff" / "0.rec";
  const GroundMotion motion = read_acceleration_column(file, AccelerationUnits::g, 0.01);
  ASSERT_EQ(motion.acceleration.size(), 3000u);
  EXPECT_EQ(motion.dt, 0.01);
  EXPECT_EQ(motion.acceleration[0], 0.0);
  EXPECT_DOUBLE_EQ(motion.acceleration[1], 3.49305e-05 * kStandardGravity);
  EXPECT_EQ(motion.name, "0");
}

TEST(AccelerationColumn, SharedRecEqualsItsAt2Source) {
  // SOURCES.md: 34.rec is RIO270.AT2 to the 6 digits kept (max |diff| 5e-7 g).
  const GroundMotion rec = read_acceleration_column(kGroundMotions / "fema_p695_ff" / "34.rec",
                                                    AccelerationUnits::g, 0.02);
  const GroundMotion at2 = read_peer_at2(kGroundMotions / "RIO270.AT2");
  ASSERT_EQ(rec.acceleration.size(), at2.acceleration.size());
  // Rounding to 6 digits moves a value by at most 5e-7 g here; the 1e-6 relative slack covers
  // the rounding of the two products by g in double precision.
  const double tolerance = 5e-7 * (1.0 + 1e-6) * kStandardGravity;
  for (std::size_t i = 0; i < rec.acceleration.size(); ++i)
    ASSERT_NEAR(rec.acceleration[i], at2.acceleration[i], tolerance) << i;
}

TEST(AccelerationColumn, ErrorsNameTheLine) {
  testing::ScratchDirectory scratch;
  const auto two_values = scratch.write("two.rec", "0.1\n0.2 0.3\n");
  try {
    read_acceleration_column(two_values, AccelerationUnits::g, 0.01);
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "line 2") << error.what();
  }
  const auto empty = scratch.write("empty.rec", "\n\n");
  try {
    read_acceleration_column(empty, AccelerationUnits::g, 0.01);
    FAIL();
  } catch (const InputError& error) {
    EXPECT_NE(error.expected().find("empty record"), std::string::npos) << error.what();
  }
  EXPECT_THROW(read_acceleration_column(scratch.path() / "absent.rec", AccelerationUnits::g, 0.01),
               InputError);
  const auto good = scratch.write("good.rec", "0.1\n");
  EXPECT_THROW(read_acceleration_column(good, AccelerationUnits::g, 0.0), InputError);
}

TEST(LoadGroundMotion, ChoosesTheFormatFromTheExtensionAndChecksWhatEachNeeds) {
  testing::ScratchDirectory scratch;
  const auto rec = scratch.write("r.rec", "0.5\n-0.5\n");
  const auto txt = scratch.write("r.txt", "0.5\n-0.5\n");
  const auto csv = scratch.write("r.csv", "time,accel\n0,0.5\n0.02,-0.5\n");
  GroundMotionOptions options;
  options.units = AccelerationUnits::g;
  options.dt = 0.02;
  options.scale = 2.0;
  for (const auto& file : {rec, txt, csv}) {
    const GroundMotion motion = load_ground_motion(file, options);
    EXPECT_EQ(motion.dt, 0.02);
    EXPECT_EQ(motion.acceleration, (std::vector<double>{kStandardGravity, -kStandardGravity}))
        << file;
  }
  // Column files need units and dt; a CSV needs units.
  GroundMotionOptions no_units;
  no_units.dt = 0.02;
  for (const auto& file : {rec, csv}) {
    try {
      load_ground_motion(file, no_units);
      FAIL() << file;
    } catch (const InputError& error) {
      EXPECT_EQ(error.location(), "units") << error.what();
    }
  }
  GroundMotionOptions no_dt;
  no_dt.units = AccelerationUnits::g;
  try {
    load_ground_motion(rec, no_dt);
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "dt") << error.what();
  }
  // An AT2 file's DT must agree with a given one.
  GroundMotionOptions wrong_dt;
  wrong_dt.dt = 0.01;
  EXPECT_THROW(load_ground_motion(kGroundMotions / "elCentro.AT2", wrong_dt), InputError);
  // The format named explicitly wins over the extension; an unknown extension is an error.
  const auto odd = scratch.write("r.dat", "0.5\n");
  EXPECT_THROW(load_ground_motion(odd, options), InputError);
  GroundMotionOptions as_column = options;
  as_column.format = GroundMotionFormat::column;
  EXPECT_EQ(load_ground_motion(odd, as_column).acceleration.size(), 1u);
  EXPECT_EQ(ground_motion_format_named("at2"), GroundMotionFormat::at2);
  EXPECT_EQ(ground_motion_format_named("AT2"), std::nullopt);
}

} // namespace
} // namespace brb::io
