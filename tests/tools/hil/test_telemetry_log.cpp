// tools/hil/telemetry_csv reads what telemetry::CsvTelemetryWriter writes, in both modes, with the
// file's time origin; and record's run reader takes the plant log's origin line.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>

#include "common/time_origin.hpp"
#include "record/csv.hpp"
#include "record/run_csv.hpp"
#include "telemetry/csv_telemetry_writer.hpp"
#include "telemetry/telemetry_queue.hpp"
#include "tools/hil/telemetry_csv.hpp"

namespace {

using mrd::telemetry::CsvTelemetryWriter;
using mrd::telemetry::TelemetryQueue;
using mrd::telemetry::TelemetryRecord;
using namespace std::chrono_literals;

// Three records a millisecond apart starting at `start` on the loop's clock, through the real
// writer into a file; the file's text.
std::string written_file(bool force_columns, mrd::hal::Timestamp start) {
  const auto path = std::filesystem::temp_directory_path() /
                    (std::string("mrd_telemetry_log_") + (force_columns ? "force" : "table4") + ".csv");
  TelemetryQueue q(16);
  CsvTelemetryWriter writer(q, 3600.0, force_columns);
  EXPECT_TRUE(writer.start(path.string()).ok);
  for (int i = 0; i < 3; ++i) {
    TelemetryRecord r{};
    r.cycle = static_cast<std::uint64_t>(i);
    r.time = start + i * 1ms;
    r.displacement = 0.01 * i;
    r.state = static_cast<std::uint8_t>(mrd::control::SupervisorState::kRun);
    r.latched = i == 2;
    r.recoveries = static_cast<std::uint64_t>(i);
    r.demand = -1500.0 * i;
    r.yield_force = 800.0;
    r.demand_check = static_cast<std::uint8_t>(mrd::control::SampleCheck::kStale);
    r.clipped = i == 1;
    r.reached = true;
    r.force_scale = 1.0 - 0.125 * i;
    r.load_cell_frozen = static_cast<std::uint32_t>(7 * i);
    q.offer(r);
  }
  writer.stop();
  const std::string text = mrd::record::read_text_file(path.string());
  std::filesystem::remove(path);
  return text;
}

TEST(TelemetryLog, TheWritersFileCarriesItsOriginAndReadsBackInBothModes) {
  const auto start = 8123456789012ns;  // 8123.456789012 s on CLOCK_MONOTONIC
  for (const bool force : {false, true}) {
    const auto log = mrd::tools::parse_telemetry_csv(written_file(force, start), "t.csv");
    EXPECT_EQ(log.force_mode, force);
    ASSERT_TRUE(log.time_origin.has_value());
    EXPECT_DOUBLE_EQ(*log.time_origin, 8123.456789012);
    ASSERT_EQ(log.rows.size(), 3u);
    EXPECT_DOUBLE_EQ(log.rows[2].time, 0.002);
    EXPECT_DOUBLE_EQ(log.rows[2].displacement, 0.02);
    EXPECT_EQ(log.rows[2].state, mrd::control::SupervisorState::kRun);
    EXPECT_TRUE(log.rows[2].latched);
    EXPECT_FALSE(log.rows[1].latched);
    EXPECT_EQ(log.rows[2].recoveries, 2u);
    if (force) {
      EXPECT_DOUBLE_EQ(log.rows[2].demand, -3000.0);
      EXPECT_DOUBLE_EQ(log.rows[0].yield_force, 800.0);
      EXPECT_EQ(log.rows[0].demand_check, "stale");
      EXPECT_TRUE(log.rows[1].clipped);
      EXPECT_FALSE(log.rows[2].clipped);
      EXPECT_TRUE(log.rows[0].reached);
      EXPECT_DOUBLE_EQ(log.rows[2].force_scale, 0.75);
      EXPECT_EQ(log.rows[1].load_cell_frozen, 7u);
    } else {
      EXPECT_EQ(log.rows[2].demand, 0.0);
      EXPECT_TRUE(log.rows[2].demand_check.empty());
    }
  }
}

TEST(TelemetryLog, AFileWithoutTheOriginLineHasNone) {
  const std::string text = std::string(CsvTelemetryWriter::header()) +
                           "0,0.000000,1.0000,fresh,0,0,0,0,0,0,0,0,INIT,none,0,0,0,0\n";
  const auto log = mrd::tools::parse_telemetry_csv(text, "old.csv");
  EXPECT_FALSE(log.time_origin.has_value());
  ASSERT_EQ(log.rows.size(), 1u);
  EXPECT_DOUBLE_EQ(log.rows[0].displacement, 1e-3);
}

// Columns are found by name: another order reads the same, and an older file (its
// observer force in kN) reads in N.
TEST(TelemetryLog, ColumnsAreFoundByNameInAnyOrderAndAnOldForceInKilonewtons) {
  const std::string header = CsvTelemetryWriter::header();
  const std::string row = "7,0.500000,2.5000,fresh,0.4,0,0,0,0,0,12,1500,RUN,none,0,1,0,0\n";
  const auto log = mrd::tools::parse_telemetry_csv(header + row, "now.csv");
  ASSERT_EQ(log.rows.size(), 1u);
  EXPECT_DOUBLE_EQ(log.rows[0].force, 1500.0);
  // The same row with the first two columns swapped and the force as kN.
  std::string old_header = header;
  old_header.replace(old_header.find("force_N"), 7, "force_kN");
  old_header.replace(0, std::string("cycle,time_s").size(), "time_s,cycle");
  const auto old = mrd::tools::parse_telemetry_csv(old_header + "0.500000,7,2.5000,fresh,0.4,0,0,0,0,0,12,1.5,RUN,none,0,1,0,0\n",
                                                   "old.csv");
  ASSERT_EQ(old.rows.size(), 1u);
  EXPECT_EQ(old.rows[0].cycle, 7u);
  EXPECT_DOUBLE_EQ(old.rows[0].time, 0.5);
  EXPECT_DOUBLE_EQ(old.rows[0].force, 1500.0);
  EXPECT_DOUBLE_EQ(old.rows[0].velocity, 0.012);
  EXPECT_DOUBLE_EQ(old.rows[0].measured_current, 0.4);
}

// Another tool's extra column is ignored, empty cells and all; a column named twice is refused.
TEST(TelemetryLog, AnExtraColumnIsIgnoredAndATwiceNamedOneRefused) {
  std::string header = CsvTelemetryWriter::header();
  header.insert(std::string("cycle").size(), ",note");
  const auto log = mrd::tools::parse_telemetry_csv(header + "7,,0.500000,2.5000,fresh,0.4,0,0,0,0,0,12,1500,RUN,none,0,1,0,0\n",
                                                   "extra.csv");
  ASSERT_EQ(log.rows.size(), 1u);
  EXPECT_TRUE(log.set_aside_rows.empty());
  std::string twice = CsvTelemetryWriter::header();
  twice.insert(twice.size() - 1, ",B_T");
  try {
    (void)mrd::tools::parse_telemetry_csv(twice + "7,0.500000,2.5000,fresh,0.4,0,0,0,0,0,12,1500,RUN,none,0,1,0,0,0\n", "twice.csv");
    ADD_FAILURE() << "a column named twice was read";
  } catch (const mrd::record::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("twice.csv:1: column 'B_T': the column appears twice"), std::string::npos) << e.what();
  }
}

TEST(TelemetryLog, AForeignHeaderOrARaggedRowNamesTheFileAndLine) {
  try {
    (void)mrd::tools::parse_telemetry_csv("time_s,force_N\n0,1\n", "x.csv");
    ADD_FAILURE() << "a foreign header was read";
  } catch (const mrd::record::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("x.csv:1:"), std::string::npos) << e.what();
  }
  try {
    (void)mrd::tools::parse_telemetry_csv(std::string(CsvTelemetryWriter::force_header()) +
                                              "# time_s 0 is CLOCK_MONOTONIC 5.000000000 s\n"
                                              "0,0.000000,1.0000,fresh,0,0,0,0,0,0,0,0,INIT,none,0,0,0,0\n",
                                          "f.csv");
    ADD_FAILURE() << "a table4 row under the force header was read";
  } catch (const mrd::record::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("f.csv:3:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("expected 25 fields, got 18"), std::string::npos) << e.what();
  }
}

// The error a telemetry text gets, or "" when it reads.
std::string telemetry_error(const std::string& text) {
  try {
    (void)mrd::tools::parse_telemetry_csv(text, "t.csv");
    return "";
  } catch (const mrd::record::InputError& e) {
    return e.what();
  }
}

TEST(TelemetryLog, CountsFlagsChecksAndTheOriginLineAreCheckedNotCast) {
  const std::string header = CsvTelemetryWriter::header();
  const std::string good = "0,0.000000,1.0000,fresh,0,0,0,0,0,0,0,0,INIT,none,0,0,0,0\n";
  EXPECT_EQ(telemetry_error(header + good), "");
  // A nan where the writer never writes one is a logger's failed read: the row is set aside.
  EXPECT_EQ(telemetry_error(header + "0,0.000000,1.0000,fresh,0,0,0,0,0,0,0,0,INIT,none,nan,0,0,0\n"),
            "t.csv:1: no telemetry row left (set aside: 1 non_finite (first at line 2))");
  EXPECT_EQ(telemetry_error(header + "0,0.000000,1.0000,fresh,0,0,0,0,0,0,0,0,INIT,none,0,0,0,-1\n"),
            "t.csv:2: column 'recoveries': '-1' is not a count");
  EXPECT_EQ(telemetry_error(header + "1.5,0.000000,1.0000,fresh,0,0,0,0,0,0,0,0,INIT,none,0,0,0,0\n"),
            "t.csv:2: column 'cycle': '1.5' is not a count");
  EXPECT_EQ(telemetry_error(header + "0,0.000000,1.0000,fresh,0,0,0,0,0,0,0,0,INIT,none,0,2,0,0\n"),
            "t.csv:2: column 'enable': '2' is not 0 or 1");
  EXPECT_EQ(telemetry_error(header + "0,0.000000,1.0000,fine,0,0,0,0,0,0,0,0,INIT,none,0,0,0,0\n"),
            "t.csv:2: column 'sample': unknown sample check");
  const std::string force = CsvTelemetryWriter::force_header();
  EXPECT_EQ(telemetry_error(force + "0,0.000000,1.0000,fresh,0,0,0,0,0,0,0,0,INIT,none,0,0,0,0,5,6,late,0,1,1,0\n"),
            "t.csv:2: column 'demand': unknown demand check");
  EXPECT_EQ(telemetry_error(header + "# time_s 0 is CLOCK_MONOTONIC 12,5 s\n" + good),
            "t.csv:2: a time-origin line must read '# time_s 0 is CLOCK_MONOTONIC <seconds> s'");
  EXPECT_EQ(telemetry_error(header + "# time_s 0 is CLOCK_MONOTONIC 1.0 s\n" + good +
                            "# time_s 0 is CLOCK_MONOTONIC 2.0 s\n"),
            "t.csv:4: a second time-origin line");
}

TEST(TimeOrigin, ParsesWhatItFormatsToTheNanosecondAndNothingElse) {
  char line[96];
  ASSERT_GT(mrd::format_time_origin(1234567.000000001, line, sizeof line), 0);
  EXPECT_STREQ(line, "# time_s 0 is CLOCK_MONOTONIC 1234567.000000001 s\n");
  ASSERT_TRUE(mrd::parse_time_origin(line).has_value());
  EXPECT_DOUBLE_EQ(*mrd::parse_time_origin(line), 1234567.000000001);
  EXPECT_FALSE(mrd::parse_time_origin("# time_s 0 is CLOCK_MONOTONIC s").has_value());
  EXPECT_FALSE(mrd::parse_time_origin("# time_s 0 is CLOCK_MONOTONIC 12x s").has_value());
  EXPECT_FALSE(mrd::parse_time_origin("# time_s 0 is CLOCK_MONOTONIC -1 s").has_value());
  EXPECT_FALSE(mrd::parse_time_origin("# time_s 0 is CLOCK_REALTIME 12 s").has_value());
  EXPECT_FALSE(mrd::parse_time_origin("# a comment").has_value());
}

TEST(TimeOrigin, TheRunReaderTakesTheOriginAndSkipsComments) {
  const auto run = mrd::record::parse_run_csv(
      "# mrd-plant log\n"
      "time_s,displacement_mm,current_A,force_N\n"
      "# time_s 0 is CLOCK_MONOTONIC 42.500000000 s\n"
      "0,1,0.5,10\n"
      "# a note between rows\n"
      "0.001,2,0.5,11\n",
      "plant.csv", {});
  ASSERT_TRUE(run.time_origin.has_value());
  EXPECT_DOUBLE_EQ(*run.time_origin, 42.5);
  ASSERT_EQ(run.size(), 2u);
  EXPECT_DOUBLE_EQ(run.force[1], 11.0);
}

// A column added to the table is written under its name, and the readers, which find columns by
// name, read the file still (the new column theirs to use or to ignore).
TEST(TelemetryLog, AColumnAddedToTheTableIsWrittenAndTheFileStillReads) {
  std::vector<mrd::telemetry::TelemetryColumn> columns(mrd::telemetry::kTelemetryColumns.begin(),
                                                     mrd::telemetry::kTelemetryColumns.begin() + 18);  // table4's
  columns.push_back({"coil_temperature_C", false, [](const mrd::telemetry::TelemetryRecord& r, double, char* b, std::size_t n) {
                       return std::snprintf(b, n, "%.1f", 20.0 + static_cast<double>(r.cycle));
                     }});
  mrd::telemetry::TelemetryRecord r{.cycle = 5, .displacement = 0.002, .force = 300.0};
  char line[512];
  ASSERT_GT(CsvTelemetryWriter::format(columns, r, {}, line, sizeof line, false), 0);
  const std::string header = CsvTelemetryWriter::column_line(columns, false);
  EXPECT_EQ(header, std::string(CsvTelemetryWriter::header()).insert(std::string(CsvTelemetryWriter::header()).size() - 1,
                                                                        ",coil_temperature_C"));
  EXPECT_NE(std::string(line).find(",25.0\n"), std::string::npos) << line;
  const auto log = mrd::tools::parse_telemetry_csv(header + line, "new.csv");
  ASSERT_EQ(log.rows.size(), 1u);
  EXPECT_EQ(log.rows[0].cycle, 5u);
  EXPECT_DOUBLE_EQ(log.rows[0].displacement, 0.002);
  EXPECT_DOUBLE_EQ(log.rows[0].force, 300.0);
}

}  // namespace
