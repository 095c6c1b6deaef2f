#include <gtest/gtest.h>

#include <chrono>
#include <limits>
#include <string>

#include "tests/record/input_error_of.hpp"
#include "record/run_csv.hpp"
#include "record/run_csv_writer.hpp"
#include "record/run_gaps.hpp"
#include "record/run_reader.hpp"
#include "telemetry/csv_telemetry_writer.hpp"
#include "telemetry/telemetry_record.hpp"

namespace {

using mrd::record::CoilSignal;
using mrd::record::parse_column_mapping;
using mrd::record::parse_run_csv;
using mrd::record::RunReadOptions;

// The error message, or "" when the text parses.
std::string csv_error_of(const std::string& text, const RunReadOptions& options = {},
                     const std::string& name = "run.csv") {
  return mrd::record::testing::input_error_of([&] { (void)parse_run_csv(text, name, options); });
}

RunReadOptions mapped(const char* columns) {
  RunReadOptions o;
  o.columns = parse_column_mapping(columns);
  return o;
}

const std::string kGood =
    "time_s,displacement_mm,current_A,force_kN\n0,1,0.5,1\n0.001,2,0.5,1.1\n0.002,3,0.5,1.2\n";

TEST(RunCsv, OwnFormatInAnyOrderAndUnitsConvertsToSI) {
  const auto run = parse_run_csv(
      "force_kN,current_mA,velocity_cm_s,time_ms,displacement_cm,B_T,temperature_C\n"
      "1.5,250,3,0,2,0.1,25\n"
      "1.6,250,4,1,2.1,0.2,25.5\n",
      "own.csv");
  ASSERT_EQ(run.size(), 2u);
  EXPECT_DOUBLE_EQ(run.time[1], 0.001);
  EXPECT_DOUBLE_EQ(run.displacement[0], 0.02);
  EXPECT_DOUBLE_EQ(run.coil[0], 0.25);
  EXPECT_EQ(run.coil_signal, CoilSignal::kCurrent);
  EXPECT_EQ(run.coil_source, "current_mA");
  EXPECT_DOUBLE_EQ(run.force[1], 1600.0);
  EXPECT_DOUBLE_EQ(run.velocity[1], 0.04);
  EXPECT_DOUBLE_EQ(run.B[1], 0.2);
  EXPECT_DOUBLE_EQ(run.temperature[1], 25.5);
  EXPECT_DOUBLE_EQ(run.sample_rate, 1000.0);
  EXPECT_TRUE(run.notes.empty());
}

TEST(RunCsv, OwnFormatWhitespaceSeparatedWithVoltageAndNoForce) {
  const auto run =
      parse_run_csv("time_s displacement_m voltage_V\n0 0.01 2.25\n0.5 0.02 0\n", "own.txt");
  EXPECT_EQ(run.coil_signal, CoilSignal::kCommandVoltage);
  EXPECT_DOUBLE_EQ(run.coil[0], 2.25);
  EXPECT_FALSE(run.has_force());
  EXPECT_DOUBLE_EQ(run.sample_rate, 2.0);
}

TEST(RunCsv, CurrentWinsOverVoltageAndSaysSo) {
  const auto run =
      parse_run_csv("time_s,displacement_mm,voltage_V,current_A\n0,1,2,0.3\n1,1,2,0.3\n", "x.csv");
  EXPECT_EQ(run.coil_signal, CoilSignal::kCurrent);
  EXPECT_DOUBLE_EQ(run.coil[0], 0.3);
  ASSERT_EQ(run.notes.size(), 1u);
  EXPECT_EQ(run.notes[0], "column 'voltage_V' ignored: the run has the coil current ('current_A')");
}

TEST(RunCsv, DykeMappingQuotedHeaderTrailingCommaAndRateOnRowOne) {
  const std::string text =
      "\"t\",\"A\",\"D\",\"Y\",\"fs\",\"V\",\"F\",\n"
      "0,-32.3798,0.021147,2.2551,3004.8,7.8095,946.961,\n"
      "0.0003328,-31.0326,0.023891,2.2554,,7.5231,945.2964,\n"
      "0.0006656,-29.5357,0.026439,2.2554,,7.3596,943.2157,\n"
      "\n";
  const auto run = parse_run_csv(text, "ranran_50.csv",
                                 mapped("t=time_s,D=displacement_cm,Y=voltage_V,F=force_N"));
  ASSERT_EQ(run.size(), 3u);
  EXPECT_DOUBLE_EQ(run.displacement[1], 0.023891e-2);
  EXPECT_DOUBLE_EQ(run.coil[2], 2.2554);
  EXPECT_EQ(run.coil_signal, CoilSignal::kCommandVoltage);
  EXPECT_DOUBLE_EQ(run.force[0], 946.961);
  EXPECT_FALSE(run.has_velocity());
  ASSERT_EQ(run.notes.size(), 1u);
  EXPECT_EQ(run.notes[0], "columns not mapped, ignored: A, fs, V");
}

TEST(RunCsv, QuirozByPositionWithTheCurrentFromTheFileName) {
  const std::string text =
      "   0.0000000e+00  -1.0251414e-01   1.0850000e+00  -1.4680551e+01\n"
      "   5.0000000e-03  -9.6714141e-02   1.1600000e+00  -1.1163642e+01\n";
  auto options = mapped("1=time_s,2=displacement_mm,3=velocity_mm_s,4=force_N");
  options.current_from_name = true;
  const auto run = parse_run_csv(text, "sine/25mm0x25Hz0x5A.txt", options);
  ASSERT_EQ(run.size(), 2u);
  EXPECT_DOUBLE_EQ(run.coil[1], 0.5);
  EXPECT_EQ(run.coil_source, "file name: 0.5 A");
  EXPECT_DOUBLE_EQ(run.velocity[1], 1.16e-3);
  EXPECT_DOUBLE_EQ(run.force[1], -11.163642);
  EXPECT_DOUBLE_EQ(run.sample_rate, 200.0);

  options.current_from_name = false;
  options.current = 0.75;
  EXPECT_DOUBLE_EQ(parse_run_csv(text, "q.txt", options).coil[0], 0.75);
}

TEST(RunCsv, CurrentFromFileName) {
  using mrd::record::current_from_file_name;
  EXPECT_DOUBLE_EQ(*current_from_file_name("data/sine/25mm0x25Hz0x5A.txt"), 0.5);
  EXPECT_DOUBLE_EQ(*current_from_file_name("5mm3Hz1A.txt"), 1.0);
  EXPECT_DOUBLE_EQ(*current_from_file_name("2mm5Hz0A.txt"), 0.0);
  EXPECT_DOUBLE_EQ(*current_from_file_name("run_0p75A.csv"), 0.75);
  EXPECT_FALSE(current_from_file_name("run.csv"));
  EXPECT_FALSE(current_from_file_name("A.txt"));
  EXPECT_FALSE(current_from_file_name("x0x5Hz.txt"));
}

TEST(RunCsv, SampleRateStandsInForAMissingTimeColumn) {
  auto options = mapped("x_mm=displacement_mm,F_0p4A_N=force_N");
  options.current = 0.4;
  options.sample_rate = 1000.0;
  const auto run =
      parse_run_csv("x_mm,F_0p2A_N,F_0p4A_N\n1,2,3\n4,5,6\n7,8,9\n", "validation.csv", options);
  EXPECT_DOUBLE_EQ(run.time[2], 0.002);
  EXPECT_DOUBLE_EQ(run.force[1], 6.0);
}

TEST(RunCsvErrors, TextWhereANumberBelongsNamesLineAndColumn) {
  std::string text = kGood;
  text.replace(text.find("0.5,1.1"), 3, "abc");
  EXPECT_EQ(csv_error_of(text), "run.csv:3: column 'current_A': 'abc' is not a finite number");
}

// What loggers do costs only the rows it touched: each is set aside with its reason and line, the
// rest of the file is read.
TEST(RunCsvSetAside, EmptyAndNonFiniteCellsSetTheirRowAside) {
  const std::string text =
      "time_s,displacement_mm,current_A,force_kN\n0,1,0.5,1\n0.001,nan,0.5,1.1\n0.002,3,,1.2\n"
      "0.003,4,0.5,-INF\n0.004,5,0.5,1.4\n";
  const auto run = parse_run_csv(text, "run.csv");
  ASSERT_EQ(run.size(), 2u);
  EXPECT_DOUBLE_EQ(run.time[1], 0.004);
  EXPECT_DOUBLE_EQ(run.force[1], 1400.0);
  ASSERT_EQ(run.set_aside_rows.size(), 3u);
  EXPECT_EQ(run.set_aside_rows[0].reason, "non_finite");
  EXPECT_EQ(run.set_aside_rows[0].line, 3u);
  EXPECT_EQ(run.set_aside_rows[0].column, "displacement_mm");
  EXPECT_EQ(run.set_aside_rows[0].next_sample, 1u);
  EXPECT_EQ(run.set_aside_rows[1].column, "current_A");
  EXPECT_EQ(run.set_aside_rows[2].column, "force_kN");
  EXPECT_EQ(run.notes.back(), "rows set aside: 3 non_finite (first at line 3)");
}

TEST(RunCsvSetAside, ARepeatedRowIsADuplicateAndAnotherAtTheSameTimeAConflict) {
  const std::string text =
      "time_s,displacement_mm,current_A\n0,1,0\n0.001,2,0\n0.001,2,0\n0.001,2.5,0\n0.0005,9,0\n0.002,3,0\n";
  const auto run = parse_run_csv(text, "run.csv");
  EXPECT_EQ(run.time, (std::vector<double>{0.0, 0.001, 0.002}));
  EXPECT_DOUBLE_EQ(run.displacement[1], 0.002);  // the first of the repeats is kept
  ASSERT_EQ(run.set_aside_rows.size(), 3u);
  EXPECT_EQ(run.set_aside_rows[0].reason, "duplicate");
  EXPECT_EQ(run.set_aside_rows[0].line, 4u);
  EXPECT_EQ(run.set_aside_rows[1].reason, "time_conflict");  // same time, another value
  EXPECT_EQ(run.set_aside_rows[2].reason, "time_conflict");  // time going back
  EXPECT_EQ(run.set_aside_rows[2].line, 6u);
  EXPECT_EQ(run.notes.back(), "rows set aside: 1 duplicate (first at line 4), 2 time_conflict (first at line 5)");
}

// A time written far ahead would otherwise make every row after it go back: the two rows after
// it agree with each other and with the rows before, so it is the one set aside.
TEST(RunCsvSetAside, ATimeWrittenFarAheadIsTheRowSetAsideNotTheRest) {
  const std::string text =
      "time_s,displacement_mm,current_A\n0,1,0\n0.001,2,0\n9,3,0\n0.003,4,0\n0.004,5,0\n0.005,6,0\n";
  const auto run = parse_run_csv(text, "run.csv");
  EXPECT_EQ(run.time, (std::vector<double>{0.0, 0.001, 0.003, 0.004, 0.005}));
  ASSERT_EQ(run.set_aside_rows.size(), 1u);
  EXPECT_EQ(run.set_aside_rows[0].reason, "time_conflict");
  EXPECT_EQ(run.set_aside_rows[0].line, 4u);
}

TEST(RunCsvErrors, AClockThatJumpsBackIsAnErrorNotTheRestOfTheFileSetAside) {
  std::string text = "time_s,displacement_mm,current_A\n";
  for (int i = 0; i < 40; ++i) text += std::to_string(0.001 * (i < 10 ? i + 100 : i)) + ",1,0\n";
  EXPECT_EQ(csv_error_of(text),
            "run.csv:31: column 'time_s': time stays behind 0.109 s for 20 rows from line 12: the clock jumped back; "
            "split the file there");
}

// Gaps are filled only where they are gaps: a time column coarser than the period (800 Hz written
// to the millisecond) is left as it is and keeps its rate, and a timestamp far off is refused
// rather than filled with millions of samples.
TEST(RunGaps, OnlyRareLongStepsAreGapsAndAFarTimestampIsRefused) {
  std::string coarse = "time_s,displacement_mm,current_A\n";
  for (int i = 0; i < 800; ++i) {
    char row[64];
    std::snprintf(row, sizeof row, "%.3f,%d,0\n", i / 800.0, i % 9);
    coarse += row;
  }
  const auto run = parse_run_csv(coarse, "coarse.csv");
  EXPECT_NEAR(run.sample_rate, 800.0, 1.0);
  const mrd::record::GapFilledRun same = mrd::record::fill_gaps(run);
  EXPECT_TRUE(same.gaps.empty());
  EXPECT_EQ(same.run.size(), run.size());

  std::string far = "time_s,displacement_mm,current_A\n";
  for (int i = 0; i < 100; ++i) far += std::to_string(i == 99 ? 3600.0 : 0.001 * i) + ",1,0\n";
  const auto stray = parse_run_csv(far, "far.csv");
  EXPECT_EQ(mrd::record::testing::input_error_of([&] { (void)mrd::record::fill_gaps(stray); }), "far.csv: the logging gaps would take 3599902 filled samples, more than 4 times the run's 100: a timestamp far off, or separate runs in one file (split it)");
}

TEST(RunCsvErrors, AFileWithTooFewUsableRowsSaysHowManyWereSetAside) {
  EXPECT_EQ(csv_error_of("time_s,displacement_mm,current_A\n0,1,0\n0,1,0\n0,nan,0\n"),
            "run.csv:1: a run needs at least 2 samples, got 1 (2 rows set aside)");
}

TEST(RunCsvErrors, MissingColumns) {
  EXPECT_EQ(csv_error_of("displacement_mm,current_A\n1,0\n2,0\n"),
            "run.csv:1: no time column: expected time_s or time_ms (or give --sample-rate)");
  EXPECT_EQ(csv_error_of("time_s,current_A\n1,0\n2,0\n"),
            "run.csv:1: no displacement column: expected displacement_m, displacement_mm or "
            "displacement_cm");
  EXPECT_EQ(csv_error_of("time_s,displacement_mm,force_N\n1,0,0\n2,0,0\n"),
            "run.csv:1: no coil current: expected a current_A or current_mA column, a voltage_V "
            "column, or --current / --current-from-name");
  EXPECT_EQ(csv_error_of("\"t\",\"D\",\n0,1,\n", mapped("t=time_s,D=displacement_cm,F=force_N"),
                     "ranran_50.csv"),
            "ranran_50.csv:1: column 'F': mapped by --columns but not in the header (t, D)");
  EXPECT_EQ(csv_error_of("0 1 2 3\n1 1 2 3\n", mapped("1=time_s,2=displacement_mm,5=force_N"), "q.txt"),
            "q.txt:1: column '5': no such column: the first row has 4");
}

TEST(RunCsvErrors, UnknownUnitsAndColumns) {
  EXPECT_EQ(csv_error_of("time_s,displacement_in,current_A\n0,1,0\n"),
            "run.csv:1: column 'displacement_in': unknown unit 'in' for displacement; expected "
            "displacement_m, displacement_mm or displacement_cm");
  EXPECT_EQ(csv_error_of("time_s,displacement_mm,current_A,pressure_bar\n0,1,0,1\n")
                .rfind("run.csv:1: column 'pressure_bar': unknown column; expected time_s, ", 0),
            0u);
  EXPECT_EQ(csv_error_of("time_s,displacement_mm,displacement_m,current_A\n0,1,1,0\n"),
            "run.csv:1: column 'displacement_m': a second displacement column (the first is "
            "'displacement_mm')");
  EXPECT_EQ(csv_error_of("time_s,,current_A\n0,1,0\n"), "run.csv:1: column '2': empty column name");
}

TEST(RunCsvErrors, RaggedRows) {
  EXPECT_EQ(csv_error_of("time_s,displacement_mm,current_A,force_kN\n0,1,0.5,1\n0.001,2,0.5\n"),
            "run.csv:3: column 'force_kN': ragged row: 3 fields, but the header has 4");
  EXPECT_EQ(csv_error_of("time_s,displacement_mm,current_A,force_kN\n0,1,0.5,1,7\n"),
            "run.csv:2: column '5': ragged row: 5 fields, but the header has 4");
  EXPECT_EQ(csv_error_of("0 1 2\n1 1\n", mapped("1=time_s,2=displacement_mm,3=current_A"), "q.txt"),
            "q.txt:2: column '3': ragged row: 2 fields, but the first row has 3");
}

TEST(RunCsvErrors, OptionsThatContradictTheFile) {
  RunReadOptions current;
  current.current = 0.5;
  EXPECT_EQ(csv_error_of(kGood, current),
            "run.csv:1: column 'current_A': the file has a coil column; --current and "
            "--current-from-name are for files without one");
  RunReadOptions rate;
  rate.sample_rate = 100.0;
  EXPECT_EQ(csv_error_of(kGood, rate),
            "run.csv:1: column 'time_s': --sample-rate is for files without a time column");
  rate.sample_rate = std::numeric_limits<double>::infinity();
  EXPECT_EQ(csv_error_of("displacement_mm,current_A\n1,0\n2,0\n", rate),
            "run.csv:1: --sample-rate must be a finite number > 0");
  current.current = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(csv_error_of("time_s,displacement_mm\n0,1\n1,1\n", current),
            "--current must be a finite number");
  RunReadOptions from_name;
  from_name.current_from_name = true;
  EXPECT_EQ(csv_error_of("time_s,displacement_mm\n0,1\n1,1\n", from_name),
            "run.csv: no coil current in the file name: expected it to end in <current>A, with x "
            "for the decimal point, as in 25mm0x25Hz0x5A.txt");
}

TEST(RunCsvErrors, TooShortEmptyOrAHeaderWhereDataBelongs) {
  EXPECT_EQ(csv_error_of(""),
            "run.csv:0: empty file: expected a header (time_s, displacement_mm, ...)");
  EXPECT_EQ(csv_error_of("time_s,displacement_mm,current_A\n0,1,0\n"),
            "run.csv:1: a run needs at least 2 samples, got 1");
  auto positional = mapped("1=time_s,2=displacement_mm");
  positional.current = 1.0;
  EXPECT_EQ(csv_error_of("t D\n0 1\n", positional, "q.txt"),
            "q.txt:1: column '1': 't' is not a finite number");
}

TEST(RunCsv, OwnFormatWriterRoundTrips) {
  const auto run = parse_run_csv(kGood, "run.csv");
  const auto again = parse_run_csv(mrd::record::format_run_csv(run), "again.csv");
  EXPECT_EQ(again.time, run.time);
  EXPECT_EQ(again.force, run.force);
  for (std::size_t i = 0; i < run.size(); ++i)
    EXPECT_NEAR(again.displacement[i], run.displacement[i], 1e-15);
}

TEST(RunCsvFiles, ReadsTheDykeFile) {
  RunReadOptions o = mapped("t=time_s,D=displacement_cm,Y=voltage_V,F=force_N");
  const auto run =
      mrd::record::read_recorded_run(MRD_DATA_DIR "/damper/dyke-nees-prototype/ranran_50.csv", o);
  EXPECT_EQ(run.size(), 74068u);
  EXPECT_NEAR(run.sample_rate, 3004.8, 0.05);
  EXPECT_EQ(run.coil_signal, CoilSignal::kCommandVoltage);
  const auto sampling = mrd::record::summarize_sampling(run.time);
  EXPECT_EQ(sampling.gaps, 0u);
  EXPECT_NEAR(sampling.min_period, 3e-4, 1e-9);  // the time column is rounded to 0.1 ms
  EXPECT_NEAR(sampling.max_period, 4e-4, 1e-9);
}

TEST(RunCsvFiles, ReadsAQuirozFileAndTheValidationRecord) {
  RunReadOptions o = mapped("1=time_s,2=displacement_mm,3=velocity_mm_s,4=force_N");
  o.current_from_name = true;
  const auto run =
      mrd::record::read_recorded_run(MRD_DATA_DIR "/damper/quiroz-utfsm/sine/5mm3Hz0x75A.txt", o);
  EXPECT_EQ(run.size(), 4187u);
  EXPECT_NEAR(run.sample_rate, 1000.0, 1e-6);
  EXPECT_DOUBLE_EQ(run.coil[0], 0.75);

  RunReadOptions v = mapped("x_mm=displacement_mm,F_1p0A_N=force_N");
  v.current = 1.0;
  v.sample_rate = 1000.0;
  const auto validation =
      mrd::record::read_recorded_run(MRD_DATA_DIR "/damper/quiroz-utfsm/validation.csv", v);
  EXPECT_EQ(validation.size(), 64648u);
}

}  // namespace

TEST(RunCsvWriter, WritesTheChosenColumnsInFileUnits) {
  const mrd::record::RunCsvWriter writer({.coil_signal = mrd::record::CoilSignal::kCommandVoltage,
                                          .velocity = true,
                                          .temperature = true,
                                          .significant_digits = 6});
  EXPECT_EQ(writer.header(), "time_s,displacement_mm,voltage_V,force_N,velocity_mm_s,temperature_C\n");
  std::string text;
  writer.append_row({.time = 0.5, .displacement = 0.0125, .coil = 1.25, .force = -850.0, .velocity = -0.0625,
                     .B = 9.0, .temperature = 41.5},
                    text);
  EXPECT_EQ(text, "0.5,12.5,1.25,-850,-62.5,41.5\n");
  char small[8];
  EXPECT_EQ(writer.format_row({}, small), 0u);
}

TEST(RunCsvWriter, AWrittenRunReadsBackInSi) {
  std::string text = mrd::record::RunCsvWriter({.B = true}).header();
  mrd::record::RunCsvWriter({.B = true}).append_row({0.0, 0.001, 0.5, 1234.5, 0, 0.25, 0}, text);
  mrd::record::RunCsvWriter({.B = true}).append_row({0.001, 0.002, 0.5, 1250.0, 0, 0.3, 0}, text);
  const auto run = parse_run_csv(text, "written.csv");
  ASSERT_EQ(run.size(), 2u);
  EXPECT_DOUBLE_EQ(run.force[1], 1250.0);
  EXPECT_DOUBLE_EQ(run.displacement[0], 0.001);
  EXPECT_DOUBLE_EQ(run.B[1], 0.3);
}

// The controller's own telemetry file reads without --columns: its header is recognised.
TEST(RunCsv, TheControllersTelemetryReadsWithoutAColumnMapping) {
  std::string text = mrd::telemetry::CsvTelemetryWriter::header();
  const mrd::hal::Timestamp start{};
  for (int i = 0; i < 3; ++i) {
    mrd::telemetry::TelemetryRecord r;
    r.cycle = static_cast<std::uint64_t>(i);
    r.time = start + std::chrono::milliseconds(i);
    r.displacement = 0.001 * i;      // [m]
    r.measured_current = 0.5 + i;    // [A]
    r.scheduled_current = 9.0;       // a second current the reader must not take
    r.velocity = 0.02;               // [m/s]
    r.force = 1234.0;                // the observer's, not a measurement
    char line[512];
    mrd::telemetry::CsvTelemetryWriter::format(r, start, line, sizeof line);
    text += line;
  }
  const auto run = mrd::record::parse_run_csv(text, "telemetry.csv", {});
  ASSERT_EQ(run.size(), 3u);
  EXPECT_DOUBLE_EQ(run.time[2], 0.002);
  EXPECT_NEAR(run.displacement[2], 0.002, 1e-9);
  EXPECT_DOUBLE_EQ(run.coil[1], 1.5);
  EXPECT_NEAR(run.velocity[0], 0.02, 1e-9);
  EXPECT_FALSE(run.has_force());
  ASSERT_FALSE(run.notes.empty());
  EXPECT_NE(run.notes.front().find("controller's telemetry"), std::string::npos);
}
