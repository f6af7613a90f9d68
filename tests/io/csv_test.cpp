// CSV: reading the strain column (and naming file, line and column on every malformed input),
// writing numbers at full precision.
#include "brb/io/csv.hpp"
#include "brb/io/input_error.hpp"
#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace brb::io {
namespace {

TEST(CsvColumn, ReadsTheNamedColumnAmongOthers) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("history.csv", "step,strain,time\n"
                                                 "1,0.001,0.5\n"
                                                 "2,-2.5e-3,1.0\n"
                                                 "3,0,1.5\n");
  const NumericColumn column = read_numeric_column(file, "strain");
  EXPECT_EQ(column.values, (std::vector<double>{0.001, -2.5e-3, 0.0}));
  EXPECT_EQ(column.lines, (std::vector<std::size_t>{2, 3, 4}));
}

TEST(CsvColumn, ToleratesQuotesSpacesCommentsBlankLinesCrlfAndBom) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("history.csv", "\xEF\xBB\xBF# imposed strain\r\n"
                                                 "strain , step\r\n"
                                                 "\r\n"
                                                 " \"1e-3\" ,1\r\n"
                                                 "# a comment\r\n"
                                                 "+2e-3,2\r\n");
  const NumericColumn column = read_numeric_column(file, "strain");
  EXPECT_EQ(column.values, (std::vector<double>{1e-3, 2e-3}));
  EXPECT_EQ(column.lines, (std::vector<std::size_t>{4, 6}));
}

TEST(CsvColumn, ReadsNumbersExactly) {
  // Correctly rounded parsing: the text of a double reads back to the same double.
  testing::ScratchDirectory scratch;
  std::mt19937_64 generator(42);
  std::uniform_real_distribution<double> strain(-0.05, 0.05);
  std::vector<double> written;
  std::string text = "strain\n";
  for (int i = 0; i < 200; ++i) {
    written.push_back(strain(generator));
    text += format_number(written.back()) + "\n";
  }
  EXPECT_EQ(read_numeric_column(scratch.write("h.csv", text), "strain").values, written);
}

struct MalformedCsv {
  std::string name;
  std::string text;
  std::string location; ///< where the error must point
};

void PrintTo(const MalformedCsv& malformed, std::ostream* out) {
  *out << malformed.name;
}

class CsvColumnRejects : public ::testing::TestWithParam<MalformedCsv> {};

TEST_P(CsvColumnRejects, WithFileAndLine) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.write("history.csv", GetParam().text);
  try {
    read_numeric_column(file, "strain");
    FAIL() << GetParam().name << " was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), file.string());
    EXPECT_EQ(error.location(), GetParam().location);
    EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos);
  }
}

INSTANTIATE_TEST_SUITE_P(
    EachMalformedFile, CsvColumnRejects,
    ::testing::Values(
        MalformedCsv{"empty_file", "", ""}, MalformedCsv{"only_comments", "# nothing\n\n", ""},
        MalformedCsv{"header_only", "strain\n", ""},
        MalformedCsv{"missing_strain_column", "step,stress\n1,2\n", "line 1 (header)"},
        MalformedCsv{"misspelt_column_after_comment", "# eps\nstrain_\n0.1\n", "line 2 (header)"},
        MalformedCsv{"duplicated_column", "strain,strain\n1,2\n", "line 1 (header)"},
        MalformedCsv{"not_a_number", "strain\n0.001\nabc\n", "line 3, column strain"},
        MalformedCsv{"trailing_garbage", "strain\n0.001x\n", "line 2, column strain"},
        MalformedCsv{"empty_cell", "step,strain\n1,\n", "line 2, column strain"},
        MalformedCsv{"nan", "strain\n0.001\nnan\n", "line 3, column strain"},
        MalformedCsv{"infinity", "strain\n-inf\n", "line 2, column strain"},
        MalformedCsv{"overflow", "strain\n1e400\n", "line 2, column strain"},
        MalformedCsv{"too_few_cells", "step,strain\n1,0.1\n2\n", "line 3"},
        MalformedCsv{"too_many_cells", "step,strain\n1,0.1,7\n", "line 2"},
        MalformedCsv{"unclosed_quote", "strain\n\"0.1\n", "line 2"}),
    [](const ::testing::TestParamInfo<MalformedCsv>& info) { return info.param.name; });

TEST(CsvColumn, MissingFileIsAnInputErrorNamingIt) {
  testing::ScratchDirectory scratch;
  const auto file = scratch.path() / "absent.csv";
  try {
    read_numeric_column(file, "strain");
    FAIL() << "a missing file was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), file.string());
  }
  EXPECT_THROW(read_numeric_column(scratch.path(), "strain"), InputError);
}

TEST(FormatNumber, IsShortestRoundTrip) {
  std::mt19937_64 generator(7);
  std::uniform_real_distribution<double> exponent(-300.0, 300.0);
  for (int i = 0; i < 1000; ++i) {
    const double value = (i % 2 ? -1.0 : 1.0) * std::pow(10.0, exponent(generator));
    const std::string text = format_number(value);
    double read = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), read);
    EXPECT_EQ(read, value) << text;
  }
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(format_number(-275.0), "-275");
  EXPECT_EQ(format_number(std::numeric_limits<double>::denorm_min()), "5e-324");
}

TEST(NumericTable, WritesHeaderAndRows) {
  NumericTable table({"strain", "stress"});
  table.append_row(std::vector<double>{0.001, 210.0});
  table.append_row(std::vector<double>{-0.5, 1.0 / 3.0});
  EXPECT_EQ(table.row_count(), 2u);
  EXPECT_EQ(table.text(), "strain,stress\n0.001,210\n-0.5," + format_number(1.0 / 3.0) + "\n");
  EXPECT_THROW(table.append_row(std::vector<double>{1.0}), std::invalid_argument);
}

} // namespace
} // namespace brb::io
