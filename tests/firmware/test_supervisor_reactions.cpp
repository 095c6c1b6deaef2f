// The supervisor's reaction to each scripted fault, in control periods, through the whole loop
// on the mock HAL. Time is a ManualClock: nothing sleeps. The numbers asserted here are the
// "reaction" column of the transition table in docs/FIRMWARE.md (default safety limits).
#include <gtest/gtest.h>

#include "tests/firmware/loop_fixture.hpp"

namespace {

using namespace mrd::test::reaction_terms;

TEST(SupervisorReaction, StartsInInitAndRunsAfterRecoveryPeriodsGoodPeriods) {
  LoopRig rig;
  EXPECT_EQ(rig.step(), kInit);
  EXPECT_EQ(rig.hal().driver.last_setpoint(), kLimits.fail_safe_current);
  EXPECT_FALSE(rig.hal().lines.enabled());
  EXPECT_EQ(rig.run_until(kRun), kLimits.recovery_periods - 1);
  EXPECT_TRUE(rig.hal().lines.enabled());
  EXPECT_EQ(rig.loop().supervisor().transitions().get(kInit, kRun, Trigger::kGoodPeriods), 1u);
}

TEST(SupervisorReaction, SensorTimeoutDegradesAtOnceAndIsSafeAfterStalePeriodsPlusOne) {
  LoopRig rig(script_of(FaultKind::kSensorTimeout));
  const Reaction r = react(rig);
  EXPECT_EQ(r.degraded, kFaultStart);
  EXPECT_EQ(r.safe, kFaultStart + kLimits.stale_periods);  // the 6th period without a sample
  expect_recovery(r);
  const auto& t = rig.loop().supervisor().transitions();
  EXPECT_EQ(t.get(kRun, kDegraded, Trigger::kSampleMissing), 1u);
  EXPECT_EQ(t.get(kDegraded, kSafe, Trigger::kSensorStale), 1u);
  EXPECT_EQ(t.get(kSafe, kRun, Trigger::kGoodPeriods), 1u);
}

TEST(SupervisorReaction, StaleRepeatedSampleIsTreatedLikeNoSample) {
  LoopRig rig(script_of(FaultKind::kStaleValue));
  const Reaction r = react(rig);
  EXPECT_EQ(r.degraded, kFaultStart);
  EXPECT_EQ(r.safe, kFaultStart + kLimits.stale_periods);
  expect_recovery(r);
}

// A bus that delivers late: each sample new (its own sequence number) but stamped twice the
// allowed age (stale_periods periods) before the cycle.
TEST(SupervisorReaction, AnOldSampleWithANewSequenceNumberIsTreatedLikeNoSample) {
  const double max_age = kLimits.stale_periods * std::chrono::duration<double>(LoopRig::kPeriod).count();
  LoopRig rig(script_of(FaultKind::kOldTimestamp, 2.0 * max_age));
  const Reaction r = react(rig);
  EXPECT_EQ(r.degraded, kFaultStart);
  EXPECT_EQ(r.safe, kFaultStart + kLimits.stale_periods);
  expect_recovery(r);
  EXPECT_EQ(rig.loop().supervisor().transitions().get(kDegraded, kSafe, Trigger::kSensorStale), 1u);
}

// A frozen LVDT: new frames, one value (the sensor or its converter stuck).
TEST(SupervisorReaction, FrozenValueIsABadSampleAfterFrozenPeriodsRepeatsWhenChecked) {
  SupervisorConfig limits;
  limits.frozen_periods = 20;
  LoopRig rig(script_of(FaultKind::kFrozenValue), limits);
  const Reaction r = react(rig);
  EXPECT_EQ(r.degraded, kFaultStart + limits.frozen_periods);  // its 21st repeat
  EXPECT_EQ(r.safe, kFaultStart + limits.frozen_periods + limits.bad_sample_periods - 1);
  // The sensor's first live value after 50 ms frozen lies 4.8 mm from the frozen one: a jump
  // (4.8 m/s in a period), so the first good period is the one after.
  expect_recovery(r, kFaultEnd + 1);
  const auto& t = rig.loop().supervisor().transitions();
  EXPECT_EQ(t.get(kRun, kDegraded, Trigger::kSampleFrozen), 1u);
  EXPECT_EQ(t.get(kDegraded, kSafe, Trigger::kSampleFrozen), 1u);
}

TEST(SupervisorReaction, FrozenValueGoesUnseenWithTheCheckOff) {
  LoopRig rig(script_of(FaultKind::kFrozenValue));
  rig.run_to(kFaultStart);
  const double frozen = rig.loop().last().displacement;
  while (rig.cycle() < kFaultEnd) {
    EXPECT_EQ(rig.step(), kRun);
    EXPECT_EQ(rig.loop().last().displacement, frozen);
  }
}

class BadSampleReaction : public ::testing::TestWithParam<std::pair<FaultKind, Trigger>> {};

TEST_P(BadSampleReaction, SafeAfterBadSamplePeriodsConsecutiveBadSamples) {
  const auto [kind, trigger] = GetParam();
  // 0.2 m is the out-of-range value and 0.2 s the future; a 20 mm jump stays in range.
  LoopRig rig(script_of(kind, kind == FaultKind::kDisplacementJump ? 0.02 : 0.2));
  const Reaction r = react(rig);
  EXPECT_EQ(r.degraded, kFaultStart);
  EXPECT_EQ(r.safe, kFaultStart + kLimits.bad_sample_periods - 1);
  expect_recovery(r);
  const auto& t = rig.loop().supervisor().transitions();
  EXPECT_EQ(t.get(kRun, kDegraded, trigger), 1u);
  EXPECT_EQ(t.get(kDegraded, kSafe, trigger), 1u);
  // The bad values were never used: the law held the last good displacement (|x| <= 30 mm).
  EXPECT_LE(std::abs(rig.loop().last().displacement), 0.030);
}

INSTANTIATE_TEST_SUITE_P(
    Kinds, BadSampleReaction,
    ::testing::Values(std::pair{FaultKind::kNotANumber, Trigger::kSampleNotFinite},
                      std::pair{FaultKind::kOutOfRange, Trigger::kSampleOutOfRange},
                      std::pair{FaultKind::kCorruptedFrame, Trigger::kSampleCorrupted},
                      std::pair{FaultKind::kDisplacementJump, Trigger::kSampleJump},
                      std::pair{FaultKind::kFutureTimestamp, Trigger::kSampleFromFuture}));

TEST(SupervisorReaction, DriverFaultLineIsSafeInTheSamePeriodWithFailSafeCurrentAndEnableCleared) {
  LoopRig rig(script_of(FaultKind::kDriverFault));
  rig.run_to(kFaultStart);
  ASSERT_EQ(rig.loop().state(), kRun);
  ASSERT_TRUE(rig.hal().lines.enabled());
  EXPECT_EQ(rig.step(), kSafe);
  EXPECT_EQ(rig.hal().driver.last_setpoint(), kLimits.fail_safe_current);
  EXPECT_FALSE(rig.hal().lines.enabled());
  rig.run_to(kFaultEnd);
  EXPECT_EQ(rig.loop().state(), kSafe);
  EXPECT_EQ(rig.run_until(kRun), kFaultEnd + kLimits.recovery_periods - 1);
  EXPECT_EQ(rig.loop().supervisor().transitions().get(kRun, kSafe, Trigger::kDriverFault), 1u);
}

TEST(SupervisorReaction, UnreadableFaultLineIsAFault) {
  LoopRig rig(script_of(FaultKind::kFaultLineUnreadable));
  const Reaction r = react(rig);
  EXPECT_EQ(r.degraded, -1);
  EXPECT_EQ(r.safe, kFaultStart);
  expect_recovery(r);
}

TEST(SupervisorReaction, CurrentDisagreementIsSafeAfterDisagreementPeriods) {
  LoopRig rig(script_of(FaultKind::kCurrentBias, 0.5));
  const Reaction r = react(rig);
  EXPECT_EQ(r.degraded, kFaultStart);
  EXPECT_EQ(r.safe, kFaultStart + kLimits.current_disagreement_periods - 1);
  expect_recovery(r);
}

TEST(SupervisorReaction, BiasWithinToleranceIsNotAFault) {
  LoopRig rig(script_of(FaultKind::kCurrentBias, 0.09));
  const Reaction r = react(rig);
  EXPECT_EQ(r.degraded, -1);
  EXPECT_EQ(r.safe, -1);
}

TEST(SupervisorReaction, FailedSetpointWritesAreSeenNextPeriodAndSafeAfterWriteFailurePeriods) {
  LoopRig rig(script_of(FaultKind::kDriverWriteFails));
  const Reaction r = react(rig);
  EXPECT_EQ(r.degraded, kFaultStart + 1);
  EXPECT_EQ(r.safe, kFaultStart + kLimits.write_failure_periods);
  // The last failed write is judged one period after the window.
  expect_recovery(r, kFaultEnd + 1);
}

TEST(SupervisorReaction, OneOverrunDegradesRepeatedOverrunsAreSafe) {
  LoopRig rig;
  rig.run_to(kFaultStart);
  EXPECT_EQ(rig.step(1), kDegraded);  // one period lost before this cycle
  rig.run_to(rig.cycle() + 20);
  EXPECT_EQ(rig.loop().state(), kRun) << "DEGRADED clears after degraded_clear_periods";
  EXPECT_EQ(rig.step(1), kDegraded);
  EXPECT_EQ(rig.step(1), kSafe);  // the third overrun within overrun_window periods
  EXPECT_EQ(rig.loop().overruns(), 3u);
  const auto safe_at = rig.cycle() - 1;
  EXPECT_EQ(rig.run_until(kRun), safe_at + kLimits.recovery_periods);
  EXPECT_EQ(rig.loop().supervisor().transitions().get(kDegraded, kSafe, Trigger::kRepeatedOverruns), 1u);
}

TEST(SupervisorReaction, OverrunsFarApartNeverAddUp) {
  SupervisorConfig limits;
  limits.overrun_window = 100;
  LoopRig rig({}, limits);
  rig.run_to(kFaultStart);
  for (int i = 0; i < 10; ++i) {
    EXPECT_NE(rig.step(1), kSafe);
    rig.run_to(rig.cycle() + limits.overrun_window);
  }
  EXPECT_EQ(rig.loop().state(), kRun);
}

TEST(SupervisorReaction, EveryOtherSampleLostStaysDegradedNeverSafe) {
  LoopRig rig(script_of(FaultKind::kDroppedSample, 2.0));
  rig.run_to(kFaultStart);
  EXPECT_EQ(rig.step(), kRun);  // the first sample of the window gets through, the second not
  for (std::int64_t i = kFaultStart + 1; i < kFaultEnd; ++i) EXPECT_EQ(rig.step(), kDegraded) << i;
  EXPECT_EQ(rig.run_until(kRun), kFaultEnd + kLimits.degraded_clear_periods - 1);
}

TEST(SupervisorReaction, HeartbeatTogglesOnlyWhileInControl) {
  LoopRig rig(script_of(FaultKind::kDriverFault));
  rig.run_to(kLimits.recovery_periods - 1);  // all of INIT
  EXPECT_EQ(rig.hal().lines.heartbeat_toggles(), 0u);
  rig.run_to(kFaultStart);  // RUN: one toggle per period
  EXPECT_EQ(rig.hal().lines.heartbeat_toggles(),
            static_cast<std::uint64_t>(kFaultStart - (kLimits.recovery_periods - 1)));
  const auto before = rig.hal().lines.heartbeat_toggles();
  rig.run_to(kFaultEnd);  // SAFE
  EXPECT_EQ(rig.hal().lines.heartbeat_toggles(), before);
}

TEST(SupervisorReaction, ShutdownDrivesFailSafeCurrentAtOnceAndNeverRecovers) {
  SupervisorConfig limits;
  limits.enable_in_safe = true;
  limits.fail_safe_current = 0.3;  // "passive on": a firm damper while stopped
  LoopRig rig({}, limits);
  rig.run_to(kFaultStart);
  ASSERT_EQ(rig.loop().state(), kRun);
  rig.loop().request_shutdown();
  EXPECT_EQ(rig.step(), kSafe);
  EXPECT_EQ(rig.hal().driver.last_setpoint(), 0.3);
  EXPECT_TRUE(rig.hal().lines.enabled());
  rig.run_to(kFaultStart + 2 * limits.recovery_periods);
  EXPECT_EQ(rig.loop().state(), kSafe);
  EXPECT_EQ(rig.loop().supervisor().transitions().get(kRun, kSafe, Trigger::kShutdown), 1u);
}

// A non-zero fail-safe current ("passive on") with enable kept: driven from the first INIT period
// and in every SAFE period of a fault, and control resumes from it under the slew limit.
TEST(SupervisorReaction, ANonZeroFailSafeCurrentHoldsInInitAndThroughAFaultsSafe) {
  SupervisorConfig limits;
  limits.enable_in_safe = true;
  limits.fail_safe_current = 0.3;
  LoopRig rig(script_of(FaultKind::kSensorTimeout), limits);
  EXPECT_EQ(rig.step(), kInit);
  EXPECT_EQ(rig.hal().driver.last_setpoint(), 0.3);
  EXPECT_TRUE(rig.hal().lines.enabled());
  rig.run_to(kFaultStart);
  ASSERT_EQ(rig.loop().state(), kRun);
  ASSERT_GE(rig.run_until(kSafe), kFaultStart);
  std::int64_t safe_periods = 1;
  EXPECT_EQ(rig.hal().driver.last_setpoint(), 0.3);
  while (rig.step() == kSafe) {
    ++safe_periods;
    ASSERT_EQ(rig.hal().driver.last_setpoint(), 0.3) << "cycle " << rig.cycle() - 1;
    ASSERT_TRUE(rig.hal().lines.enabled());
  }
  EXPECT_GT(safe_periods, limits.recovery_periods);
  ASSERT_EQ(rig.loop().state(), kRun);
  // 100 A/s at 1 kHz: 0.1 A per period from the fail-safe current.
  EXPECT_NEAR(rig.hal().driver.last_setpoint(), 0.3, 0.1 + 1e-9);
}

TEST(SupervisorReaction, ControlResumesFromTheFailSafeCurrentNotFromTheOldCommand) {
  LoopRig rig(script_of(FaultKind::kDriverFault));
  rig.run_to(kFaultStart);
  const auto r = rig.run_until(kRun);
  ASSERT_GT(r, 0);
  // The slew limit (100 A/s at 1 kHz: 0.1 A per period) applies from 0 A after SAFE.
  EXPECT_LE(rig.hal().driver.last_setpoint(), 0.1 + 1e-9);
}

}  // namespace
