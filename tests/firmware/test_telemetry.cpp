#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "telemetry/csv_telemetry_writer.hpp"
#include "telemetry/telemetry_queue.hpp"
#include "tests/firmware/loop_fixture.hpp"
#include "tests/hal/test_wait.hpp"
#include "tests/support/test_files.hpp"

namespace {

using mrd::telemetry::CsvTelemetryWriter;
using mrd::telemetry::TelemetryQueue;
using mrd::telemetry::TelemetryRecord;

TEST(TelemetryQueue, AFullRingDropsAndCountsNeverLosesSilently) {
  TelemetryQueue q(16);
  for (int i = 0; i < 100; ++i) q.offer(TelemetryRecord{static_cast<std::uint64_t>(i)});
  std::uint64_t first = 0;
  bool seen = false;
  const std::size_t popped = q.drain([&](const TelemetryRecord& r) {
    if (!seen) first = r.cycle;
    seen = true;
  });
  EXPECT_EQ(first, 0u);  // the oldest records stay, the newest are dropped
  EXPECT_EQ(q.offered(), 100u);
  EXPECT_EQ(popped + q.dropped(), q.offered());
  EXPECT_EQ(popped, 16u);
}

TEST(TelemetryLoop, EveryCycleIsWrittenOrCountedAsDropped) {
  const auto path = std::filesystem::temp_directory_path() / "mrd_telemetry_test.csv";
  TelemetryQueue q(64);  // small: the loop outruns a writer that drains only at the end
  mrd::test::LoopRig rig({}, {}, &q);
  CsvTelemetryWriter writer(q, 3600.0);  // drains at stop() only
  ASSERT_TRUE(writer.start(path.string()).ok);
  constexpr int kCycles = 1000;
  for (int i = 0; i < kCycles; ++i) rig.step();
  writer.stop();
  EXPECT_EQ(q.offered(), static_cast<std::uint64_t>(kCycles));
  EXPECT_EQ(writer.written(), 64u);
  EXPECT_EQ(writer.written() + q.dropped(), static_cast<std::uint64_t>(kCycles));

  std::ifstream in(path);
  std::string line;
  // The time origin first, a comment before the column line (pandas.read_csv(f, comment='#')):
  // the rig's clock starts at 0.
  std::getline(in, line);
  EXPECT_EQ(line, "# time_s 0 is CLOCK_MONOTONIC 0.000000000 s");
  std::getline(in, line);
  EXPECT_EQ(line + "\n", CsvTelemetryWriter::header());
  std::getline(in, line);
  EXPECT_EQ(line.rfind("0,0.000000,0.0000,fresh,", 0), 0u) << line;
  EXPECT_NE(line.find(",INIT,none,0,0"), std::string::npos) << line;
  int rows = 1;
  while (std::getline(in, line)) ++rows;
  EXPECT_EQ(rows, 64);
  std::filesystem::remove(path);
}

// A run that ends before its first record still leaves a file that says what it would have held.
TEST(TelemetryLoop, ARunWithNoRecordLeavesTheColumnLine) {
  const auto path = std::filesystem::temp_directory_path() / "mrd_telemetry_empty.csv";
  TelemetryQueue q(16);
  CsvTelemetryWriter writer(q, 3600.0);
  ASSERT_TRUE(writer.start(path.string()).ok);
  writer.stop();
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, CsvTelemetryWriter::header());
  EXPECT_EQ(writer.failures(), 0u);
  std::filesystem::remove(path);
}

TEST(TelemetryLoop, AWriterThatKeepsUpDropsNothing) {
  const auto path = std::filesystem::temp_directory_path() / "mrd_telemetry_test2.csv";
  TelemetryQueue q(4096);
  mrd::test::LoopRig rig({}, {}, &q);
  CsvTelemetryWriter writer(q, 0.001);
  ASSERT_TRUE(writer.start(path.string()).ok);
  constexpr int kCycles = 3000;
  for (int i = 0; i < kCycles; ++i) {
    rig.step();
    // Pace the producer against the consumer: never more than half the ring ahead.
    if (i % 1000 == 999) {
      ASSERT_TRUE(mrd::test::wait_for([&] { return writer.written() == q.offered(); }));
    }
  }
  writer.stop();
  EXPECT_EQ(q.dropped(), 0u);
  EXPECT_EQ(writer.written(), static_cast<std::uint64_t>(kCycles));
  std::filesystem::remove(path);
}

TEST(TelemetryLoop, DecimationOffersOneRecordEveryNCycles) {
  TelemetryQueue q(1024);
  auto hal = std::make_unique<mrd::hal::mock::MockHal>();
  mrd::firmware::ControlLoop loop({}, {}, {hal->lvdt, hal->driver, hal->lines}, &q, 10);
  for (int i = 0; i < 95; ++i) {
    hal->clock.set(mrd::hal::mock::cycle_time(i, mrd::test::LoopRig::kPeriod));
    loop.step(hal->clock.now());
  }
  EXPECT_EQ(q.offered(), 10u);  // cycles 0, 10, ..., 90
  std::uint64_t last = 0;
  q.drain([&](const TelemetryRecord& r) { last = r.cycle; });
  EXPECT_EQ(last, 90u);
}

}  // namespace

namespace {

using mrd::telemetry::TelemetryConfig;

// A fresh directory for one test's telemetry files.
class TelemetryFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    config_.directory = dir_.path().string();
    config_.path = "run.csv";
  }

  // One start of the writer: `cycles` cycles of the loop, then stop.
  std::string one_run(int cycles, TelemetryQueue& q) {
    mrd::test::LoopRig rig({}, {}, &q);
    CsvTelemetryWriter writer(q, 3600.0);
    EXPECT_TRUE(writer.start(config_).ok);
    for (int i = 0; i < cycles; ++i) rig.step();
    writer.stop();
    EXPECT_EQ(writer.written() + writer.capped() + q.dropped(), q.offered());
    capped_ = writer.capped();
    return writer.path();
  }
  static std::size_t lines(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::size_t n = 0;
    for (std::string line; std::getline(in, line);) ++n;
    return n;
  }

  mrd::test::TestDirectory dir_{"mrd_telemetry_runs"};
  TelemetryConfig config_;
  std::uint64_t capped_ = 0;
};

TEST_F(TelemetryFiles, EachStartWritesItsOwnNumberedFileAndKeepsTheLastRunsRecord) {
  TelemetryQueue first(1024);
  EXPECT_EQ(one_run(300, first), (dir_ / "run-0001.csv").string());
  TelemetryQueue second(1024);
  EXPECT_EQ(one_run(200, second), (dir_ / "run-0002.csv").string());
  EXPECT_EQ(lines(dir_ / "run-0001.csv"), 302u);  // header, time origin and every row of the first run
  EXPECT_EQ(lines(dir_ / "run-0002.csv"), 202u);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "run.csv"));

  // Numbers continue after the highest there, whatever else the directory holds.
  std::ofstream(dir_ / "run-0041.csv") << "an earlier run\n";
  std::ofstream(dir_ / "run-notes.csv") << "not a run\n";
  TelemetryQueue third(1024);
  EXPECT_EQ(one_run(10, third), (dir_ / "run-0042.csv").string());
  EXPECT_EQ(lines(dir_ / "run-0041.csv"), 1u);
}

TEST_F(TelemetryFiles, TheSizeCapIsHonouredAndWhatItKeptOutIsCounted) {
  config_.max_bytes = 8192;
  TelemetryQueue q(4096);
  const std::string path = one_run(1000, q);  // about 100 bytes a row: 100 kB uncapped
  EXPECT_LE(std::filesystem::file_size(path), 8192u);
  EXPECT_GT(std::filesystem::file_size(path), 8192u - 512u);  // filled up to the last row that fits
  EXPECT_GT(capped_, 800u);
  EXPECT_EQ(q.dropped(), 0u);
}

TEST_F(TelemetryFiles, WithoutPerRunThePathItselfIsWritten) {
  config_.per_run = false;
  TelemetryQueue q(1024);
  EXPECT_EQ(one_run(5, q), (dir_ / "run.csv").string());
}

}  // namespace

namespace {

TEST(TelemetryForceColumns, ForceModeAppendsItsColumnsAndTable4LinesAreUnchanged) {
  mrd::telemetry::TelemetryRecord r{};
  r.demand = 12345.0;
  r.yield_force = 9876.5;
  r.demand_check = static_cast<std::uint8_t>(mrd::control::SampleCheck::kStale);
  r.clipped = true;
  r.reached = false;
  r.force_scale = 0.875;
  r.load_cell_frozen = 12;
  char table4[512];
  char force[512];
  const int n4 = mrd::telemetry::CsvTelemetryWriter::format(r, {}, table4, sizeof table4);
  const int nf = mrd::telemetry::CsvTelemetryWriter::format(r, {}, force, sizeof force, true);
  ASSERT_GT(n4, 0);
  const std::string base(table4, static_cast<std::size_t>(n4));
  const std::string line(force, static_cast<std::size_t>(nf));
  EXPECT_EQ(line, base.substr(0, base.size() - 1) + ",12345,9876.5,stale,1,0,0.875,12\n");
  const std::string header = mrd::telemetry::CsvTelemetryWriter::header();
  EXPECT_EQ(std::string(mrd::telemetry::CsvTelemetryWriter::force_header()),
            header.substr(0, header.size() - 1) +
                ",demand_N,yield_force_N,demand,clipped,reached,force_scale,load_cell_frozen\n");
}

}  // namespace

namespace {

// Every field of a record lands in its named column, in the file's unit, written out by hand
// here: the writer's column table must keep each value under its own name.
TEST(TelemetryColumns, EachFieldIsWrittenUnderItsNameInTheFilesUnit) {
  using mrd::control::SampleCheck;
  using mrd::control::SupervisorState;
  using mrd::control::Trigger;
  mrd::telemetry::TelemetryRecord r{
      .cycle = 42,
      .time = mrd::hal::Timestamp{std::chrono::milliseconds{1500}},
      .displacement = 0.0123,
      .measured_current = 0.51,
      .scheduled_current = 0.8,
      .law_current = 0.75,
      .setpoint = 0.7,
      .target_B = 0.9,
      .B = 0.85,
      .velocity = 0.0456,
      .force = 12345.6,
      .overruns = 3,
      .sample = static_cast<std::uint8_t>(SampleCheck::kFresh),
      .state = static_cast<std::uint8_t>(SupervisorState::kRun),
      .trigger = static_cast<std::uint8_t>(Trigger::kNone),
      .enable = true,
      .latched = false,
      .recoveries = 7,
      .demand = 2000.0,
      .yield_force = 9876.5,
      .demand_check = static_cast<std::uint8_t>(SampleCheck::kStale),
      .clipped = true,
      .reached = false,
      .force_scale = 0.875,
      .load_cell_frozen = 12,
  };
  char line[512];
  ASSERT_GT(mrd::telemetry::CsvTelemetryWriter::format(r, {}, line, sizeof line, true), 0);
  EXPECT_STREQ(line,
               "42,1.500000,12.3000,fresh,0.51,0.8,0.75,0.7,0.9,0.85,45.6,12345.6,RUN,none,3,1,0,7,"
               "2000,9876.5,stale,1,0,0.875,12\n");
  EXPECT_STREQ(mrd::telemetry::CsvTelemetryWriter::force_header(),
               "cycle,time_s,displacement_mm,sample,measured_current_A,scheduled_current_A,law_current_A,setpoint_A,"
               "target_B_T,B_T,velocity_mm_s,force_N,state,trigger,overruns,enable,latched,recoveries,"
               "demand_N,yield_force_N,demand,clipped,reached,force_scale,load_cell_frozen\n");
}

}  // namespace
