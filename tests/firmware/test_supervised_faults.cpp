// The faults the supervisor judges beyond the LVDT's value and the fault line: a silent current
// readback, refused setpoints, failed line writes, a driver that cannot be disabled, repeated
// driver faults (the latch), a non-finite command, observer recoveries and an overrun count
// beyond 32 bits. Through the whole loop on the mock HAL, in control periods; nothing sleeps.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tests/firmware/loop_fixture.hpp"

namespace {

using namespace mrd::test::reaction_terms;

FaultScript window(FaultKind kind, std::int64_t from, std::int64_t to, double parameter = 0.0) {
  return FaultScript{{kind, cycle_time(from, LoopRig::kPeriod), cycle_time(to, LoopRig::kPeriod), parameter}};
}

TEST(SupervisedFault, AOneSampleSpikeCostsTwoBadSamplesAndNeverReachesSafe) {
  LoopRig rig(window(FaultKind::kDisplacementJump, kFaultStart, kFaultStart + 1, 0.005));
  const Reaction r = react(rig);
  EXPECT_EQ(r.degraded, kFaultStart);
  EXPECT_EQ(r.safe, -1);
  EXPECT_EQ(rig.loop().supervisor().transitions().get(kRun, kDegraded, Trigger::kSampleJump), 1u);
}

TEST(SupervisedFault, AJumpWithinMaxSpeedIsMotion) {
  SupervisorConfig limits;
  limits.max_speed = 10.0;  // 10 mm in a 1 ms period
  LoopRig rig(window(FaultKind::kDisplacementJump, kFaultStart, kFaultStart + 1, 0.005), limits);
  EXPECT_EQ(react(rig).degraded, -1);
}

TEST(SupervisedFault, ASilentReadbackIsSafeOncePastTheTimeoutAndNotBefore) {
  LoopRig rig(window(FaultKind::kReadbackSilent, kFaultStart, kFaultStart + 200));
  const Reaction r = react(rig);
  EXPECT_EQ(r.degraded, -1) << "a reading may come slower than the loop: no soft step";
  // The last reading came at kFaultStart - 1; 51 periods later it is older than 50.
  EXPECT_EQ(r.safe, kFaultStart + kLimits.readback_timeout_periods);
  expect_recovery(r, kFaultStart + 200);
  EXPECT_EQ(rig.loop().supervisor().transitions().get(kRun, kSafe, Trigger::kReadbackLost), 1u);

  LoopRig exactly(window(FaultKind::kReadbackSilent, kFaultStart, kFaultStart + kLimits.readback_timeout_periods));
  EXPECT_EQ(react(exactly).safe, -1) << "silent for exactly the timeout is not yet lost";
}

TEST(SupervisedFault, AReadbackThatNeverCameIsAFaultOnlyWhenRequired) {
  const FaultScript silent = window(FaultKind::kReadbackSilent, 0, 100000);
  LoopRig optional(silent);
  EXPECT_EQ(optional.run_until(kRun), kLimits.recovery_periods - 1);

  SupervisorConfig limits;
  limits.require_readback = true;
  LoopRig required(silent, limits);
  EXPECT_EQ(required.run_until(kSafe), kLimits.readback_timeout_periods + 1);
  EXPECT_EQ(required.loop().supervisor().transitions().get(kInit, kSafe, Trigger::kReadbackLost), 1u);
  EXPECT_EQ(required.run_until(kRun, 5000), -1);
}

TEST(SupervisedFault, RefusedSetpointsAreSeenNextPeriodAndSafeAfterWriteFailurePeriods) {
  LoopRig rig(script_of(FaultKind::kSetpointRefused));
  const Reaction r = react(rig);
  EXPECT_EQ(r.degraded, kFaultStart + 1);
  EXPECT_EQ(r.safe, kFaultStart + kLimits.write_failure_periods);
  expect_recovery(r, kFaultEnd + 1);  // the last refusal is reported the period after
  const auto& t = rig.loop().supervisor().transitions();
  EXPECT_EQ(t.get(kRun, kDegraded, Trigger::kSetpointRefused), 1u);
  EXPECT_EQ(t.get(kDegraded, kSafe, Trigger::kSetpointRefused), 1u);
  EXPECT_EQ(rig.hal().driver.setpoint_acks().refused, static_cast<std::uint64_t>(kFaultEnd - kFaultStart));
}

TEST(SupervisedFault, FailedHeartbeatWritesDegradeAndAreSafeAfterLineFailurePeriods) {
  LoopRig rig(script_of(FaultKind::kHeartbeatWriteFails));
  const Reaction r = react(rig);
  EXPECT_EQ(r.degraded, kFaultStart + 1);
  EXPECT_EQ(r.safe, kFaultStart + kLimits.line_failure_periods);
  // SAFE toggles no heartbeat, so the next period is good.
  EXPECT_EQ(r.run_again, r.safe + kLimits.recovery_periods);
  EXPECT_EQ(rig.loop().supervisor().transitions().get(kDegraded, kSafe, Trigger::kLineWriteFailed), 1u);
  EXPECT_FALSE(rig.loop().supervisor().latched());
}

TEST(SupervisedFault, ADriverThatCannotBeDisabledLatchesSafeUntilAnOperatorClears) {
  FaultScript script = script_of(FaultKind::kDriverFault);
  script.add({FaultKind::kEnableWriteFails, cycle_time(kFaultStart, LoopRig::kPeriod),
              cycle_time(kFaultStart + 300, LoopRig::kPeriod), 0.0});
  LoopRig rig(script);
  rig.run_to(kFaultStart);
  EXPECT_EQ(rig.step(), kSafe);
  EXPECT_EQ(rig.hal().driver.last_setpoint(), kLimits.fail_safe_current) << "the 0 A setpoint still holds it";
  rig.run_to(kFaultStart + kLimits.line_failure_periods);
  EXPECT_FALSE(rig.loop().supervisor().latched());
  rig.step();
  EXPECT_TRUE(rig.loop().supervisor().latched());
  EXPECT_TRUE(rig.loop().last().latched);
  EXPECT_EQ(rig.loop().last().trigger, static_cast<std::uint8_t>(Trigger::kDisableFailed));
  // Long after both faults have gone (the enable write retried until it took): still SAFE.
  rig.run_to(kFaultStart + 2000);
  EXPECT_EQ(rig.loop().state(), kSafe);
  EXPECT_FALSE(rig.hal().lines.enabled());
  rig.loop().request_clear_latch();
  const auto cleared_at = rig.cycle();
  EXPECT_EQ(rig.run_until(kRun), cleared_at + kLimits.recovery_periods - 1);
  EXPECT_EQ(rig.loop().supervisor().transitions().get(kSafe, kSafe, Trigger::kOperatorClear), 1u);
}

FaultScript driver_faults_every(std::int64_t spacing) {
  FaultScript script;
  for (int k = 0; k < 3; ++k) {
    const std::int64_t at = kFaultStart + k * spacing;
    script.add({FaultKind::kDriverFault, cycle_time(at, LoopRig::kPeriod), cycle_time(at + 10, LoopRig::kPeriod), 0.0});
  }
  return script;
}

TEST(SupervisedFault, TheThirdDriverFaultWithinTheWindowLatchesSafe) {
  LoopRig rig(driver_faults_every(500));
  rig.run_to(kFaultStart + 2 * 500 + 10);
  EXPECT_EQ(rig.loop().supervisor().transitions().into(kSafe), 3u);
  EXPECT_TRUE(rig.loop().supervisor().latched());
  EXPECT_EQ(rig.run_until(kRun, 10000), -1) << "latched: no recovery however long it is good";
  rig.loop().request_clear_latch();
  EXPECT_GT(rig.run_until(kRun), 0);
  EXPECT_FALSE(rig.loop().supervisor().latched());
}

TEST(SupervisedFault, DriverFaultsFurtherApartThanTheWindowNeverLatch) {
  SupervisorConfig limits;
  limits.driver_fault_window = 400;
  LoopRig rig(driver_faults_every(500), limits);
  rig.run_to(kFaultStart + 2 * 500 + 10);
  EXPECT_EQ(rig.loop().supervisor().transitions().into(kSafe), 3u);
  EXPECT_FALSE(rig.loop().supervisor().latched());
  EXPECT_GT(rig.run_until(kRun), 0);
}

TEST(SupervisedFault, ANonFiniteCommandIsNeverWrittenAndIsSafeInItsOwnPeriod) {
  mrd::control::ControlLawConfig law;
  // A corrupted schedule through the uncompensated path: the slew limiter passes the NaN on.
  law.compensate_hysteresis = false;
  law.schedule.currents.fill(std::numeric_limits<double>::quiet_NaN());
  LoopRig rig({}, {}, nullptr, law);
  for (std::int64_t i = 0; i < 3 * kLimits.recovery_periods; ++i) {
    rig.step();
    ASSERT_TRUE(std::isfinite(rig.hal().driver.last_setpoint())) << "cycle " << i;
    ASSERT_NE(rig.loop().state(), kRun) << "cycle " << i;
  }
  const auto& t = rig.loop().supervisor().transitions();
  EXPECT_EQ(t.get(kRun, kSafe, Trigger::kCommandNotFinite), t.into(kRun));
  EXPECT_GE(t.into(kRun), 2u) << "each recovery tried the law once, and was vetoed";
  EXPECT_EQ(rig.hal().driver.last_setpoint(), kLimits.fail_safe_current);
}

// Ms = 1e308 (past the config's bounds, as a corrupted model would be): the current stays
// finite but target_B is NaN, so the law controls nothing; vetoed and counted like a NaN current.
TEST(SupervisedFault, ANonFiniteTargetIsVetoedLikeANonFiniteCommand) {
  mrd::control::ControlLawConfig law;
  law.damper.jiles_atherton.Ms = 1e308;
  LoopRig rig({}, {}, nullptr, law);
  for (std::int64_t i = 0; i < 3 * kLimits.recovery_periods; ++i) {
    rig.step();
    ASSERT_NE(rig.loop().state(), kRun) << "cycle " << i;
  }
  const auto& t = rig.loop().supervisor().transitions();
  EXPECT_GE(t.get(kRun, kSafe, Trigger::kCommandNotFinite), 2u) << "each recovery tried the law once, and was vetoed";
  EXPECT_EQ(t.get(kRun, kSafe, Trigger::kCommandNotFinite), t.into(kRun));
  EXPECT_EQ(rig.hal().driver.last_setpoint(), kLimits.fail_safe_current);
}

TEST(SupervisedFault, ObserverRecoveriesAreCountedInTelemetryAndSafeAfterRecoveryPeriods) {
  // A corrupted pinning constant: every J-A step that moves the field ends non-finite and the
  // observer resets to the anhysteretic curve (a recovery). INIT holds the current, so the
  // first recoveries come when the law starts driving the coil.
  mrd::control::ControlLawConfig law;
  law.damper.jiles_atherton.k = std::numeric_limits<double>::quiet_NaN();
  LoopRig rig({}, {}, nullptr, law);
  const std::int64_t safe_at = rig.run_until(kSafe);
  ASSERT_GT(safe_at, 0);
  EXPECT_EQ(rig.loop().last().trigger, static_cast<std::uint8_t>(Trigger::kObserverRecovery));
  EXPECT_GE(rig.loop().last().recoveries, static_cast<std::uint64_t>(kLimits.observer_recovery_periods));
  EXPECT_EQ(rig.loop().last().recoveries, rig.loop().law().observer().magnetics().recoveries());
}

TEST(SupervisedFault, AnOverrunCountBeyondThirtyTwoBitsIsSaturatedNotWrapped) {
  LoopRig rig;
  rig.run_to(kFaultStart);
  ASSERT_EQ(rig.loop().state(), kRun);
  // 2^32 + 2 lost periods: wrapped to 32 bits this would read as 2 (DEGRADED only).
  EXPECT_EQ(rig.step((std::int64_t{1} << 32) + 2), kSafe);
  EXPECT_EQ(rig.loop().last().overruns, std::numeric_limits<std::uint32_t>::max());
  EXPECT_EQ(rig.loop().supervisor().transitions().get(kRun, kSafe, Trigger::kRepeatedOverruns), 1u);
}

}  // namespace
