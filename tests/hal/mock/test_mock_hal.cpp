#include "hal/mock/mock_hal.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace std::chrono_literals;
using mrd::hal::IoStatus;
using mrd::hal::Timestamp;
using namespace mrd::hal::mock;

constexpr Timestamp kPeriod = 1ms;

TEST(FaultScript, WindowsAreHalfOpenAndQueriesFindTheRightKind) {
  const FaultScript script{{FaultKind::kCurrentBias, 10ms, 20ms, 0.3},
                           {FaultKind::kDriverFault, 15ms, 16ms, 0.0}};
  EXPECT_FALSE(script.is_active(FaultKind::kCurrentBias, 9ms));
  ASSERT_NE(script.active(FaultKind::kCurrentBias, 10ms), nullptr);
  EXPECT_EQ(script.active(FaultKind::kCurrentBias, 19ms)->parameter, 0.3);
  EXPECT_FALSE(script.is_active(FaultKind::kCurrentBias, 20ms));
  EXPECT_FALSE(script.is_active(FaultKind::kSensorTimeout, 15ms));
  EXPECT_EQ(cycle_time(250, kPeriod), 250ms);
  EXPECT_TRUE(script.validate().ok());
}

TEST(FaultScript, ValidateNamesBadEntries) {
  const FaultScript script{{FaultKind::kSensorTimeout, 5ms, 5ms, 0.0},
                           {FaultKind::kDroppedSample, 0ms, 1ms, 0.0}};
  const auto r = script.validate();
  EXPECT_TRUE(r.mentions("faults[0].end")) << r.to_string();
  EXPECT_TRUE(r.mentions("faults[1].parameter")) << r.to_string();
}

class MockHalTest : public ::testing::Test {
 protected:
  // One call of latest() per period, starting at the current clock.
  std::optional<mrd::hal::Sample> step() {
    hal.clock.advance(kPeriod);
    return hal.lvdt.latest();
  }
  MockHal hal{FaultScript{
      {FaultKind::kSensorTimeout, cycle_time(10, kPeriod), cycle_time(13, kPeriod), 0.0},
      {FaultKind::kStaleValue, cycle_time(20, kPeriod), cycle_time(23, kPeriod), 0.0},
      {FaultKind::kNotANumber, cycle_time(30, kPeriod), cycle_time(31, kPeriod), 0.0},
      {FaultKind::kOutOfRange, cycle_time(40, kPeriod), cycle_time(41, kPeriod), 0.5},
      {FaultKind::kCorruptedFrame, cycle_time(50, kPeriod), cycle_time(51, kPeriod), 0.0},
      {FaultKind::kDroppedSample, cycle_time(60, kPeriod), cycle_time(70, kPeriod), 3.0},
  }};
};

TEST_F(MockHalTest, ReportsTheTruthWithRisingSequenceAndInjectedTime) {
  hal.lvdt.set_value(0.01);
  const auto a = step();
  hal.lvdt.set_value(-0.02);
  const auto b = step();
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->value, 0.01);
  EXPECT_EQ(b->value, -0.02);
  EXPECT_TRUE(b->usable());
  EXPECT_EQ(b->sequence, a->sequence + 1);
  EXPECT_EQ(b->timestamp - a->timestamp, kPeriod);
  EXPECT_EQ(b->timestamp, hal.clock.now());
}

TEST_F(MockHalTest, EachSensorFaultLooksAsScriptedAndEnds) {
  hal.lvdt.set_value(0.01);
  hal.clock.set(cycle_time(9, kPeriod));
  for (int c = 10; c < 13; ++c) EXPECT_FALSE(step().has_value()) << "cycle " << c;
  EXPECT_TRUE(step().has_value());  // cycle 13: back

  hal.clock.set(cycle_time(18, kPeriod));
  const auto fresh = step();  // cycle 19
  hal.lvdt.set_value(0.02);
  const auto stale = step();  // cycle 20: the old sample again, whatever the truth now is
  ASSERT_TRUE(fresh && stale);
  EXPECT_EQ(stale->sequence, fresh->sequence);
  EXPECT_EQ(stale->timestamp, fresh->timestamp);
  EXPECT_EQ(stale->value, 0.01);

  hal.clock.set(cycle_time(29, kPeriod));
  const auto nan = step();
  ASSERT_TRUE(nan.has_value());
  EXPECT_TRUE(std::isnan(nan->value));
  EXPECT_NE(nan->flags & mrd::hal::kSampleValid, 0);

  hal.clock.set(cycle_time(39, kPeriod));
  EXPECT_EQ(step()->value, 0.5);

  hal.clock.set(cycle_time(49, kPeriod));
  const auto corrupt = step();
  ASSERT_TRUE(corrupt.has_value());
  EXPECT_FALSE(corrupt->usable());
  EXPECT_NE(corrupt->flags & mrd::hal::kSampleCorrupted, 0);
  EXPECT_TRUE(step()->usable());  // cycle 51
}

TEST_F(MockHalTest, DroppedSamplesLeaveSequenceGaps) {
  hal.clock.set(cycle_time(59, kPeriod));
  int delivered = 0;
  int gaps = 0;
  for (int c = 60; c < 72; ++c) {
    if (const auto s = step()) {
      ++delivered;
      if ((s->flags & mrd::hal::kSampleSequenceGap) != 0) ++gaps;
    }
  }
  EXPECT_EQ(hal.lvdt.samples_dropped(), 3u);  // every third of the ten in the window
  EXPECT_EQ(delivered, 12 - 3);
  EXPECT_EQ(gaps, 3);
}

// One mock for the three channels, each answering only to its own faults: the LVDT's timeout
// leaves the demand and the load cell alone, the demand's missing fault the LVDT.
TEST(MockSampleSource, EachChannelAnswersOnlyToItsOwnFaults) {
  MockHal hal{FaultScript{{FaultKind::kSensorTimeout, 0ms, 10ms, 0.0},
                          {FaultKind::kDemandMissing, 10ms, 20ms, 0.0},
                          {FaultKind::kDemandOutOfRange, 20ms, 30ms, 1e9}}};
  hal.demand.set_value(250.0);
  hal.load_cell.set_value(240.0);
  hal.clock.set(5ms);
  EXPECT_FALSE(hal.lvdt.latest().has_value());
  EXPECT_EQ(hal.demand.latest()->value, 250.0);
  EXPECT_EQ(hal.load_cell.latest()->value, 240.0);
  hal.clock.set(15ms);
  EXPECT_TRUE(hal.lvdt.latest().has_value());
  EXPECT_FALSE(hal.demand.latest().has_value());
  EXPECT_TRUE(hal.load_cell.latest().has_value());
  hal.clock.set(25ms);
  EXPECT_EQ(hal.demand.latest()->value, 1e9);
  EXPECT_EQ(hal.load_cell.latest()->value, 240.0);

  hal.load_cell.set_faulty(true);
  EXPECT_FALSE(hal.load_cell.latest()->usable());
  hal.load_cell.set_silent(true);
  EXPECT_FALSE(hal.load_cell.latest().has_value());
}

TEST(MockDriverAndLines, FollowTheSetpointAndTheScript) {
  MockHal hal{FaultScript{{FaultKind::kCurrentBias, 10ms, 20ms, 0.25},
                          {FaultKind::kDriverWriteFails, 30ms, 31ms, 0.0},
                          {FaultKind::kDriverFault, 40ms, 50ms, 0.0},
                          {FaultKind::kFaultLineUnreadable, 60ms, 61ms, 0.0}}};
  EXPECT_EQ(hal.driver.measured()->value, 0.0);
  EXPECT_EQ(hal.driver.write_setpoint(1.5), IoStatus::kOk);
  EXPECT_EQ(hal.driver.measured()->value, 1.5);
  hal.clock.set(10ms);
  EXPECT_EQ(hal.driver.measured()->value, 1.75);
  EXPECT_EQ(hal.driver.measured()->timestamp, 10ms);
  hal.clock.set(30ms);
  EXPECT_EQ(hal.driver.write_setpoint(0.2), IoStatus::kIoError);
  EXPECT_EQ(hal.driver.last_setpoint(), 1.5);
  EXPECT_EQ(hal.driver.failed_writes(), 1u);

  EXPECT_EQ(hal.lines.driver_fault(), false);
  hal.clock.set(45ms);
  EXPECT_EQ(hal.lines.driver_fault(), true);
  hal.clock.set(60ms);
  EXPECT_FALSE(hal.lines.driver_fault().has_value());

  EXPECT_EQ(hal.lines.set_enable(true), IoStatus::kOk);
  EXPECT_EQ(hal.lines.set_enable(true), IoStatus::kOk);
  EXPECT_EQ(hal.lines.set_enable(false), IoStatus::kOk);
  EXPECT_EQ(hal.lines.enable_transitions(), 2u);
  EXPECT_FALSE(hal.lines.enabled());
  for (int i = 0; i < 5; ++i) EXPECT_EQ(hal.lines.toggle_heartbeat(), IoStatus::kOk);
  EXPECT_EQ(hal.lines.heartbeat_toggles(), 5u);
  EXPECT_TRUE(hal.lines.heartbeat());
}

}  // namespace
