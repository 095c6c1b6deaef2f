// The supervisor alone: a pure function of (state, inputs, now), stepped with made-up inputs.
#include "control/supervisor.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <limits>

namespace {

using namespace std::chrono_literals;
using mrd::control::SampleCheck;
using mrd::control::Supervisor;
using mrd::control::SupervisorConfig;
using mrd::control::SupervisorInputs;
using mrd::control::SupervisorState;
using mrd::control::Trigger;
using mrd::hal::Timestamp;

SupervisorConfig quick() {
  SupervisorConfig c;
  c.recovery_periods = 3;
  c.degraded_clear_periods = 2;
  return c;
}

struct Clocked {
  Supervisor sup{quick()};
  Timestamp now{};
  mrd::control::SupervisorDecision step(const SupervisorInputs& in = {}) {
    now += 1ms;
    return sup.step(in, now);
  }
};

TEST(Supervisor, InitWaitsForTheSensorWithoutTrippingAndRunsAfterRecoveryPeriods) {
  Clocked c;
  for (int i = 0; i < 100; ++i) EXPECT_EQ(c.step({SampleCheck::kMissing}).state, SupervisorState::kInit);
  EXPECT_EQ(c.step().state, SupervisorState::kInit);
  EXPECT_EQ(c.step().state, SupervisorState::kInit);
  const auto d = c.step();
  EXPECT_EQ(d.state, SupervisorState::kRun);
  EXPECT_EQ(d.trigger, Trigger::kGoodPeriods);
  EXPECT_EQ(c.sup.since(), c.now);
}

TEST(Supervisor, InitGoesSafeOnAHardFaultOtherThanSilence) {
  Clocked c;
  SupervisorInputs in;
  in.driver_fault = true;
  const auto d = c.step(in);
  EXPECT_EQ(d.state, SupervisorState::kSafe);
  EXPECT_EQ(d.trigger, Trigger::kDriverFault);
  EXPECT_FALSE(d.enable);
  EXPECT_FALSE(d.toggle_heartbeat);
}

TEST(Supervisor, TheMostSevereTriggerNamesTheTransition) {
  Clocked c;
  for (int i = 0; i < 3; ++i) c.step();
  ASSERT_EQ(c.sup.state(), SupervisorState::kRun);
  SupervisorInputs in;
  in.sample = SampleCheck::kNotFinite;
  in.current_disagrees = true;
  in.driver_fault = std::nullopt;
  EXPECT_EQ(c.step(in).trigger, Trigger::kFaultLineUnreadable);
}

TEST(Supervisor, OutputsFollowTheState) {
  SupervisorConfig cfg = quick();
  cfg.enable_in_safe = true;
  cfg.fail_safe_current = 0.2;
  Supervisor sup(cfg);
  auto d = sup.step({}, 1ms);
  EXPECT_FALSE(d.in_control);
  EXPECT_TRUE(d.enable);  // enable_in_safe
  d = sup.step({}, 2ms);
  d = sup.step({}, 3ms);
  EXPECT_TRUE(d.in_control);
  EXPECT_TRUE(d.toggle_heartbeat);
  SupervisorInputs missing;
  missing.sample = SampleCheck::kMissing;
  d = sup.step(missing, 4ms);
  EXPECT_EQ(d.state, SupervisorState::kDegraded);
  EXPECT_TRUE(d.in_control);
  EXPECT_TRUE(d.toggle_heartbeat);
}

TEST(Supervisor, TransitionsAreCountedByFromToAndTrigger) {
  Clocked c;
  SupervisorInputs missing;
  missing.sample = SampleCheck::kMissing;
  for (int round = 0; round < 4; ++round) {
    for (int i = 0; i < 3; ++i) c.step();          // -> RUN
    for (int i = 0; i < 6; ++i) c.step(missing);   // -> DEGRADED -> SAFE (after > 5)
  }
  const auto& t = c.sup.transitions();
  EXPECT_EQ(t.get(SupervisorState::kInit, SupervisorState::kRun, Trigger::kGoodPeriods), 1u);
  EXPECT_EQ(t.get(SupervisorState::kSafe, SupervisorState::kRun, Trigger::kGoodPeriods), 3u);
  EXPECT_EQ(t.get(SupervisorState::kRun, SupervisorState::kDegraded, Trigger::kSampleMissing), 4u);
  EXPECT_EQ(t.get(SupervisorState::kDegraded, SupervisorState::kSafe, Trigger::kSensorStale), 4u);
  EXPECT_EQ(t.total(), 12u);
  EXPECT_EQ(t.into(SupervisorState::kSafe), 4u);
}

TEST(Supervisor, ConfigValidationNamesEachBadKey) {
  SupervisorConfig c;
  c.stale_periods = 0;
  c.displacement_max = -1.0;
  c.fail_safe_current = 0.5;  // while enable_in_safe is false
  c.overrun_window = 0;
  const auto r = c.validate();
  EXPECT_TRUE(r.mentions("stale_periods"));
  EXPECT_TRUE(r.mentions("displacement_max"));
  EXPECT_TRUE(r.mentions("fail_safe_current"));
  EXPECT_TRUE(r.mentions("overrun_window"));
  EXPECT_EQ(r.issues().size(), 4u) << r.to_string();
  EXPECT_NE(r.to_string().find("stale_periods: must be >= 1, got 0"), std::string::npos);
}

TEST(Supervisor, RefusalsCountUntilOneSetpointIsAcceptedBetween) {
  Clocked c;
  while (c.step().state != SupervisorState::kRun) {
  }
  const SupervisorInputs refused{.setpoints_refused = 1};
  const SupervisorInputs accepted{.setpoint_accepted = true};
  // Refused, accepted, refused ...: never write_failure_periods refusals in a row.
  for (int i = 0; i < 20; ++i) EXPECT_NE(c.step(i % 2 == 0 ? refused : accepted).state, SupervisorState::kSafe);
  // Periods without any acknowledgement neither reset nor add: the back end may write slower.
  c.step(refused);
  c.step();
  c.step(refused);
  c.step();
  EXPECT_EQ(c.step(refused).state, SupervisorState::kSafe);
  EXPECT_EQ(c.sup.transitions().get(SupervisorState::kDegraded, SupervisorState::kSafe, Trigger::kSetpointRefused), 1u);
}

TEST(Supervisor, AVetoIsSafeAtOnceAndAClearOnlyMattersWhenLatched) {
  Clocked c;
  while (c.step().state != SupervisorState::kRun) {
  }
  const auto d = c.sup.veto(Trigger::kCommandNotFinite, c.now);
  EXPECT_EQ(d.state, SupervisorState::kSafe);
  EXPECT_FALSE(d.in_control);
  EXPECT_FALSE(d.enable);
  c.sup.clear_latch(c.now);  // not latched: nothing to clear, nothing counted
  EXPECT_EQ(c.sup.transitions().get(SupervisorState::kSafe, SupervisorState::kSafe, Trigger::kOperatorClear), 0u);
  EXPECT_EQ(c.step().state, SupervisorState::kSafe);
}

TEST(Supervisor, ConfigValidationNamesEachNewBadKey) {
  SupervisorConfig c;
  c.readback_timeout_periods = -1;
  c.line_failure_periods = 0;
  c.observer_recovery_periods = 0;
  c.max_speed = -1.0;
  c.driver_fault_limit = 17;
  c.driver_fault_window = 0;
  const auto r = c.validate();
  for (const char* key : {"readback_timeout_periods", "line_failure_periods", "observer_recovery_periods",
                          "max_speed", "driver_fault_limit", "driver_fault_window"}) {
    EXPECT_TRUE(r.mentions(key)) << key;
  }
  EXPECT_EQ(r.issues().size(), 6u) << r.to_string();
  SupervisorConfig waits_for_nothing;
  waits_for_nothing.require_readback = true;
  waits_for_nothing.readback_timeout_periods = 0;
  EXPECT_TRUE(waits_for_nothing.validate().mentions("require_readback"));
}

// Start-up with a link that takes a while (a Modbus device still booting): INIT waits as for a
// missing sample, its queued fail-safe setpoint is no failed write, and RUN needs the link.
SupervisorConfig linked(double timeout) {
  SupervisorConfig c = quick();
  c.link_timeout = timeout;
  return c;
}

TEST(Supervisor, InitWaitsForTheLinkUpToItsTimeoutWithoutCountingFailedWrites) {
  Clocked c{Supervisor(linked(0.010))};  // 10 periods of 1 ms, counted from the first step
  const SupervisorInputs down{.sample = SampleCheck::kMissing, .link_down = true};
  for (int i = 0; i < 5; ++i) ASSERT_EQ(c.step(down).state, SupervisorState::kInit) << "period " << i;
  // Fresh samples (another bus) while the driver's link is still down, up to 1 ms short of the
  // timeout: no RUN without the link.
  const SupervisorInputs fresh_but_down{.link_down = true};
  for (int i = 0; i < 5; ++i) ASSERT_EQ(c.step(fresh_but_down).state, SupervisorState::kInit);
  EXPECT_EQ(c.step().state, SupervisorState::kRun);  // the good periods counted while it waited
  EXPECT_EQ(c.sup.transitions().total(), 1u);
  EXPECT_EQ(c.sup.transitions().into(SupervisorState::kSafe), 0u);
}

TEST(Supervisor, ALinkStillDownAtTheTimeoutIsSafeWithItsOwnTriggerAndRecoversOnceUp) {
  Clocked c{Supervisor(linked(0.010))};
  const SupervisorInputs down{.sample = SampleCheck::kMissing, .link_down = true};
  // The first step is at 1 ms: the timeout is reached at 11 ms, the eleventh step.
  for (int i = 0; i < 10; ++i) ASSERT_EQ(c.step(down).state, SupervisorState::kInit) << "period " << i;
  const auto d = c.step(down);
  EXPECT_EQ(d.state, SupervisorState::kSafe);
  EXPECT_EQ(d.trigger, Trigger::kLinkTimeout);
  EXPECT_FALSE(d.latched);
  EXPECT_EQ(to_string(Trigger::kLinkTimeout), "link_timeout");
  // Still down in SAFE: a failed write, so no recovery; once up, RUN after recovery_periods.
  for (int i = 0; i < 10; ++i) ASSERT_EQ(c.step({.link_down = true}).state, SupervisorState::kSafe);
  EXPECT_EQ(c.step().state, SupervisorState::kSafe);
  EXPECT_EQ(c.step().state, SupervisorState::kSafe);
  EXPECT_EQ(c.step().trigger, Trigger::kGoodPeriods);
}

TEST(Supervisor, PastInitALinkDownIsAFailedWrite) {
  Clocked c{Supervisor(linked(0.010))};
  while (c.step().state != SupervisorState::kRun) {
  }
  const SupervisorInputs down{.link_down = true};
  EXPECT_EQ(c.step(down).trigger, Trigger::kSetpointWriteFailed);  // DEGRADED
  EXPECT_EQ(c.step(down).state, SupervisorState::kDegraded);
  const auto d = c.step(down);
  EXPECT_EQ(d.state, SupervisorState::kSafe);
  EXPECT_EQ(d.trigger, Trigger::kSetpointWriteFailed);
}

TEST(Supervisor, LinkTimeoutMustBeAPositiveFiniteTimeUpToAnHour) {
  for (const double bad : {0.0, -1.0, 3600.5, std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity()}) {
    SupervisorConfig c;
    c.link_timeout = bad;
    EXPECT_TRUE(c.validate().mentions("link_timeout")) << bad;
    EXPECT_EQ(c.validate().issues().size(), 1u) << bad;
  }
  SupervisorConfig longest;
  longest.link_timeout = 3600.0;
  EXPECT_TRUE(longest.validate().ok());
}

// The latch's window: driver_fault_limit driver-side SAFE entries latch when the last comes
// less than driver_fault_window periods after the first; exactly the window apart they do not.
bool latches_with_entries_apart(int periods_apart, int window) {
  SupervisorConfig cfg = quick();
  cfg.driver_fault_limit = 2;
  cfg.driver_fault_window = window;
  Clocked c{Supervisor(cfg)};
  const SupervisorInputs fault{.driver_fault = true};
  EXPECT_EQ(c.step(fault).trigger, Trigger::kDriverFault);  // INIT -> SAFE, period 1
  for (int i = 1; i < periods_apart; ++i) c.step();          // RUN again after 3
  EXPECT_EQ(c.sup.state(), SupervisorState::kRun);
  const auto d = c.step(fault);                               // period 1 + periods_apart
  EXPECT_EQ(d.state, SupervisorState::kSafe);
  return d.latched;
}

TEST(Supervisor, DriverFaultsLatchOnlyWithinTheWindow) {
  EXPECT_TRUE(latches_with_entries_apart(9, 10));
  EXPECT_FALSE(latches_with_entries_apart(10, 10));
  EXPECT_FALSE(latches_with_entries_apart(11, 10));
}

}  // namespace
