// The telemetry writer against files that fail: a full disk and a FIFO nobody reads. Every
// record is written, dropped, capped or lost, each counted; the stop never waits on the reader.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <string>

#include "telemetry/csv_telemetry_writer.hpp"
#include "telemetry/telemetry_queue.hpp"
#include "tests/firmware/loop_fixture.hpp"
#include "tests/support/test_files.hpp"

namespace {

using mrd::telemetry::CsvTelemetryWriter;
using mrd::telemetry::TelemetryQueue;
using std::chrono::milliseconds;

void expect_accounted(const CsvTelemetryWriter& writer, const TelemetryQueue& q) {
  EXPECT_EQ(writer.written() + writer.capped() + writer.lost() + q.dropped(), q.offered());
}

TEST(TelemetryFailures, AFullDiskLosesEveryRecordAndSaysWhy) {
  TelemetryQueue q(1024);
  mrd::test::LoopRig rig({}, {}, &q);
  CsvTelemetryWriter writer(q, 3600.0);  // one pass, at stop()
  ASSERT_TRUE(writer.start("/dev/full").ok);
  for (int i = 0; i < 100; ++i) rig.step();
  writer.stop();
  EXPECT_EQ(writer.written(), 0u);
  EXPECT_EQ(writer.lost(), 100u);
  EXPECT_EQ(writer.failures(), 1u);  // the pass at stop: origin, column line and records together
  EXPECT_EQ(writer.last_error(), ENOSPC);
  expect_accounted(writer, q);
}

// A FIFO whose reader holds it open and never reads: the pipe takes what fits, then nothing.
class StuckReader : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(mkfifo(fifo_.c_str(), 0600), 0);
    reader_ = open(fifo_.c_str(), O_RDONLY | O_NONBLOCK);
    ASSERT_GE(reader_, 0);
  }
  void TearDown() override { close(reader_); }
  // Everything the pipe holds.
  [[nodiscard]] std::string drain() const {
    std::string text;
    char buf[4096];
    for (ssize_t n; (n = read(reader_, buf, sizeof buf)) > 0;) text.append(buf, static_cast<std::size_t>(n));
    return text;
  }

  mrd::test::TestDirectory dir_{"mrd_telemetry_fifo"};
  std::string fifo_ = (dir_ / "telemetry.csv").string();
  int reader_ = -1;
};

TEST_F(StuckReader, WhatThePipeDoesNotTakeIsLostAndTheFileHoldsOnlyWholeLines) {
  TelemetryQueue q(4096);
  mrd::test::LoopRig rig({}, {}, &q);
  CsvTelemetryWriter writer(q, 3600.0, false, milliseconds{0});
  ASSERT_TRUE(writer.start(fifo_).ok);
  for (int i = 0; i < 2000; ++i) rig.step();  // about 200 kB, a 64 kB pipe
  writer.stop();
  EXPECT_GT(writer.written(), 100u);
  EXPECT_GT(writer.lost(), 1000u);
  EXPECT_EQ(writer.last_error(), ETIMEDOUT);
  expect_accounted(writer, q);
  // The header, the time origin and each record counted as written end in '\n'; a record cut
  // off by the pipe is counted lost, never written.
  const std::string text = drain();
  EXPECT_EQ(static_cast<std::uint64_t>(std::count(text.begin(), text.end(), '\n')), writer.written() + 2);
}

TEST_F(StuckReader, TheStopWaitsNoLongerThanTheWriteTimeout) {
  TelemetryQueue q(4096);
  mrd::test::LoopRig rig({}, {}, &q);
  CsvTelemetryWriter writer(q, 3600.0, false, milliseconds{20});
  ASSERT_TRUE(writer.start(fifo_).ok);
  for (int i = 0; i < 2000; ++i) rig.step();
  const auto before = std::chrono::steady_clock::now();
  writer.stop();
  EXPECT_LT(std::chrono::steady_clock::now() - before, milliseconds{600});  // the default would be 1 s
  EXPECT_EQ(writer.last_error(), ETIMEDOUT);
  EXPECT_GT(writer.lost(), 1000u);
  expect_accounted(writer, q);
}

TEST_F(StuckReader, AFifoWithoutAReaderIsRefusedAtStartNotWaitedFor) {
  close(reader_);
  reader_ = -1;
  TelemetryQueue q(16);
  CsvTelemetryWriter writer(q, 3600.0);
  const auto started = writer.start(fifo_);
  EXPECT_FALSE(started.ok);
  EXPECT_NE(started.error.find("cannot open telemetry file " + fifo_), std::string::npos) << started.error;
}

}  // namespace
