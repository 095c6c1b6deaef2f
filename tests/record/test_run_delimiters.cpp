// Delimited text as rigs and spreadsheets write it: the delimiter found from the header (comma,
// semicolon, tab, blanks), CRLF, a byte-order mark, a decimal comma where the delimiter is a
// semicolon; the same run in each reads the same.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "record/csv.hpp"
#include "record/run_csv.hpp"
#include "record/run_reader.hpp"
#include "tests/record/input_error_of.hpp"
#include "tests/record/support/same_run.hpp"

namespace {

using mrd::record::RecordedRun;
using mrd::record::testing::a_run;
using mrd::record::testing::as_text;
using mrd::record::testing::Columns;
using mrd::record::testing::expect_same_run;
using mrd::record::testing::input_error_of;
using mrd::record::testing::kTextColumns;

TEST(RunFormats, DelimiterFromTheHeader) {
  using mrd::record::Delimiter;
  using mrd::record::find_delimiter;
  EXPECT_EQ(find_delimiter("t;x;F"), Delimiter::kSemicolon);
  EXPECT_EQ(find_delimiter("0,5;1,25"), Delimiter::kSemicolon);  // decimal commas in a headerless row
  EXPECT_EQ(find_delimiter("t,\tx"), Delimiter::kComma);
  EXPECT_EQ(find_delimiter("t\tx\tF"), Delimiter::kTab);
  EXPECT_EQ(find_delimiter("  t  x F"), Delimiter::kBlanks);
}


TEST(RunFormats, SameRunAsCommaSemicolonTabAndBlanksWithCrlfAndBom) {
  const Columns c = a_run();
  const RecordedRun reference = mrd::record::parse_run_csv(as_text(c, ",", "\n"), "run.csv", kTextColumns);
  ASSERT_EQ(reference.size(), c.t.size());
  EXPECT_DOUBLE_EQ(reference.displacement[50], c.x[50] * 1e-3);
  const std::string bom = "\xEF\xBB\xBF";
  expect_same_run(reference,
                  mrd::record::parse_run_csv(as_text(c, ";", "\r\n", true, bom), "comma.csv", kTextColumns),
                  "semicolons, decimal commas, CRLF, BOM");
  expect_same_run(reference, mrd::record::parse_run_csv(as_text(c, ";", "\n"), "points.csv", kTextColumns),
                  "semicolons, decimal points");
  expect_same_run(reference, mrd::record::parse_run_csv(as_text(c, "\t", "\r\n", false, bom), "run.tsv", kTextColumns),
                  "tabs, CRLF, BOM");
  expect_same_run(reference, mrd::record::parse_run_csv(as_text(c, "  ", "\n"), "run.txt", kTextColumns), "blanks");
}


TEST(RunFormatsErrors, DecimalCommaOnlyWhereTheDelimiterIsASemicolon) {
  EXPECT_EQ(input_error_of([] {
              (void)mrd::record::parse_run_csv("time_s\tdisplacement_mm\tcurrent_A\n0\t1,5\t0\n", "run.tsv");
            }),
            "run.tsv:2: column 'displacement_mm': '1,5' is not a finite number");
  EXPECT_EQ(input_error_of([] {
              (void)mrd::record::parse_run_csv("time_s;displacement_mm;current_A\n0;1.000,5;0\n", "run.csv");
            }),
            "run.csv:2: column 'displacement_mm': '1.000,5' is not a finite number");
  // A tab with nothing between is an empty cell (a failed read), not a wider blank.
  const RecordedRun run =
      mrd::record::parse_run_csv("time_s\tdisplacement_mm\tcurrent_A\n0\t1\t0\n1\t\t0\n2\t3\t0\n3\t4\t0\n", "run.tsv");
  EXPECT_EQ(run.time, (std::vector<double>{0, 2, 3}));
  ASSERT_EQ(run.set_aside_rows.size(), 1u);
  EXPECT_EQ(run.set_aside_rows[0].reason, "non_finite");
}

// The committed fixtures (tests/record/data/formats/make_fixtures.py), as a user's files arrive.
TEST(RunFormats, CommittedSemicolonAndTabFilesReadAsTheirCsv) {
  const std::string dir = MRD_RECORD_TEST_DATA "/formats/";
  const RecordedRun reference = mrd::record::read_recorded_run(dir + "run.csv", kTextColumns);
  ASSERT_EQ(reference.size(), 300u);
  expect_same_run(reference, mrd::record::read_recorded_run(dir + "run_semicolon.csv", kTextColumns), "run_semicolon.csv");
  expect_same_run(reference, mrd::record::read_recorded_run(dir + "run_tab.tsv", kTextColumns), "run_tab.tsv");
}

}  // namespace
