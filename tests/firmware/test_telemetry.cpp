#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "runtime/csv_telemetry_writer.hpp"
#include "runtime/telemetry_queue.hpp"
#include "tests/firmware/loop_fixture.hpp"
#include "tests/hal/test_wait.hpp"

namespace {

using mrd::runtime::CsvTelemetryWriter;
using mrd::runtime::TelemetryQueue;
using mrd::runtime::TelemetryRecord;

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
