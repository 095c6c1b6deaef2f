// The real-time thread's feed to the others: one event per transition (with the state it left),
// the state snapshot, and a full ring that drops and counts instead of blocking.
#include "telemetry/supervisor_feed.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace {

using mrd::control::SupervisorState;
using mrd::control::Trigger;
using mrd::telemetry::SupervisorEvent;
using mrd::telemetry::SupervisorFeed;
using mrd::telemetry::TelemetryRecord;

TelemetryRecord record(std::uint64_t cycle, SupervisorState state, Trigger trigger = Trigger::kNone) {
  TelemetryRecord r;
  r.cycle = cycle;
  r.time = std::chrono::milliseconds(cycle);
  r.state = static_cast<std::uint8_t>(state);
  r.trigger = static_cast<std::uint8_t>(trigger);
  return r;
}

std::vector<SupervisorEvent> drain(SupervisorFeed& feed) {
  std::vector<SupervisorEvent> events;
  feed.drain([&](const SupervisorEvent& e) { events.push_back(e); });
  return events;
}

TEST(SupervisorFeed, EachTransitionIsOneEventWithTheStateItLeft) {
  SupervisorFeed feed;
  EXPECT_EQ(feed.state(), SupervisorState::kInit);
  feed.publish(record(0, SupervisorState::kInit));
  feed.publish(record(1, SupervisorState::kRun, Trigger::kGoodPeriods));
  feed.publish(record(2, SupervisorState::kRun));
  feed.publish(record(3, SupervisorState::kDegraded, Trigger::kOverrun));
  EXPECT_EQ(feed.state(), SupervisorState::kDegraded);
  feed.publish(record(4, SupervisorState::kSafe, Trigger::kDriverFault));
  EXPECT_EQ(feed.state(), SupervisorState::kSafe);

  const auto events = drain(feed);
  ASSERT_EQ(events.size(), 3u);
  EXPECT_EQ(events[0].cycle, 1u);
  EXPECT_EQ(events[0].from, SupervisorState::kInit);
  EXPECT_EQ(events[0].to, SupervisorState::kRun);
  EXPECT_EQ(events[1].from, SupervisorState::kRun);
  EXPECT_EQ(events[1].trigger, Trigger::kOverrun);
  EXPECT_EQ(events[2].from, SupervisorState::kDegraded);
  EXPECT_EQ(events[2].to, SupervisorState::kSafe);
  EXPECT_EQ(events[2].time, std::chrono::milliseconds(4));
  EXPECT_TRUE(drain(feed).empty());
}

// The exit status reads what took the loop into the SAFE it ended in: a fault before the stop
// stays the cause through the shutdown cycle; SAFE entered by the stop is the stop's.
TEST(SupervisorFeed, TheCauseOfTheSafeStateIsKeptWhileItLasts) {
  SupervisorFeed feed;
  EXPECT_EQ(feed.safe_cause(), Trigger::kNone);
  feed.publish(record(1, SupervisorState::kSafe, Trigger::kLinkTimeout));
  EXPECT_EQ(feed.safe_cause(), Trigger::kLinkTimeout);
  feed.publish(record(2, SupervisorState::kSafe));
  feed.publish(record(3, SupervisorState::kSafe, Trigger::kShutdown));
  EXPECT_EQ(feed.safe_cause(), Trigger::kLinkTimeout);
  feed.publish(record(4, SupervisorState::kRun, Trigger::kGoodPeriods));
  EXPECT_EQ(feed.safe_cause(), Trigger::kNone);
  // The supervisor's own sequence: RUN -> SAFE on a fault, then the shutdown cycle in SAFE
  // carries no trigger of its own.
  feed.publish(record(5, SupervisorState::kSafe, Trigger::kDriverFault));
  feed.publish(record(6, SupervisorState::kSafe));
  EXPECT_EQ(feed.safe_cause(), Trigger::kDriverFault);
  feed.publish(record(7, SupervisorState::kRun, Trigger::kGoodPeriods));
  feed.publish(record(8, SupervisorState::kSafe, Trigger::kShutdown));
  EXPECT_EQ(feed.safe_cause(), Trigger::kShutdown);
}

TEST(SupervisorFeed, TheLatchIsPublishedWithTheStateAndClearsWithIt) {
  SupervisorFeed feed;
  EXPECT_FALSE(feed.latched());
  TelemetryRecord latched = record(7, SupervisorState::kSafe, Trigger::kDriverFault);
  latched.latched = true;
  feed.publish(latched);
  EXPECT_TRUE(feed.latched());
  feed.publish(record(8, SupervisorState::kSafe, Trigger::kOperatorClear));
  EXPECT_FALSE(feed.latched());
  EXPECT_EQ(feed.state(), SupervisorState::kSafe);
}

TEST(SupervisorFeed, AFullRingDropsAndCountsTheLoopNeverWaits) {
  SupervisorFeed feed;
  const std::size_t n = SupervisorFeed::kCapacity + 10;
  for (std::size_t i = 0; i < n; ++i) {
    feed.publish(record(i, i % 2 == 0 ? SupervisorState::kDegraded : SupervisorState::kRun,
                        i % 2 == 0 ? Trigger::kSampleMissing : Trigger::kGoodPeriods));
  }
  EXPECT_EQ(feed.lost(), 10u);
  const auto events = drain(feed);
  EXPECT_EQ(events.size(), SupervisorFeed::kCapacity);
  EXPECT_EQ(events.front().cycle, 0u);  // the oldest are kept
  EXPECT_EQ(feed.state(), SupervisorState::kRun);  // the snapshot is never lost
}

TEST(SupervisorFeed, TheLoadCellScaleAtItsBoundIsCountedWithItsValueForTheJournal) {
  SupervisorFeed feed;
  EXPECT_EQ(feed.force_scale_bound_hits(), 0u);
  TelemetryRecord r = record(1, SupervisorState::kRun);
  r.force_scale = 0.9;
  feed.publish(r);
  EXPECT_EQ(feed.force_scale_bound_hits(), 0u);
  r.force_scale = 0.7;
  r.force_scale_at_bound = true;
  feed.publish(r);
  r.force_scale_at_bound = false;  // still at the bound: no new line
  feed.publish(r);
  EXPECT_EQ(feed.force_scale_bound_hits(), 1u);
  EXPECT_EQ(feed.force_scale_at_bound(), 0.7);
  EXPECT_TRUE(drain(feed).empty()) << "not a supervisor transition";
}

}  // namespace
