// Zero heap allocations per cycle over 1e5 cycles after start-up, through every supervisor path:
// each fault kind of the mock HAL, overruns, SAFE and recovery, with telemetry into the ring.
#include <gtest/gtest.h>

#include <limits>

#include "runtime/latency_histogram.hpp"
#include "runtime/loop_statistics.hpp"
#include "tests/firmware/loop_fixture.hpp"
#include "tests/support/allocation_counter.hpp"

namespace {

using mrd::control::SupervisorState;
using mrd::hal::mock::FaultKind;
using mrd::hal::mock::FaultScript;
using mrd::hal::mock::cycle_time;
using mrd::test::LoopRig;

TEST(RealTime, ControlLoopCycleDoesNotAllocateOnAnySupervisorPath) {
  FaultScript script;
  const auto window = [&script](FaultKind kind, std::int64_t from, double parameter = 0.0) {
    script.add({kind, cycle_time(from, LoopRig::kPeriod), cycle_time(from + 400, LoopRig::kPeriod),
                parameter});
  };
  // One fault after another, each followed by recovery (200 good periods).
  std::int64_t at = 1000;
  for (auto [kind, parameter] : {std::pair{FaultKind::kSensorTimeout, 0.0},
                                 std::pair{FaultKind::kStaleValue, 0.0},
                                 std::pair{FaultKind::kNotANumber, 0.0},
                                 std::pair{FaultKind::kOutOfRange, 0.5},
                                 std::pair{FaultKind::kCorruptedFrame, 0.0},
                                 std::pair{FaultKind::kDroppedSample, 2.0},
                                 std::pair{FaultKind::kDriverFault, 0.0},
                                 std::pair{FaultKind::kFaultLineUnreadable, 0.0},
                                 std::pair{FaultKind::kCurrentBias, 0.5},
                                 std::pair{FaultKind::kDriverWriteFails, 0.0},
                                 std::pair{FaultKind::kReadbackSilent, 0.0},
                                 std::pair{FaultKind::kSetpointRefused, 0.0},
                                 std::pair{FaultKind::kHeartbeatWriteFails, 0.0},
                                 std::pair{FaultKind::kDisplacementJump, 0.02},
                                 std::pair{FaultKind::kFutureTimestamp, 0.2}}) {
    window(kind, at, parameter);
    at += 1000;
  }
  // A driver fault whose disable fails: SAFE latches until the clear at kClearAt.
  constexpr std::int64_t kLatchAt = 21000;
  constexpr std::int64_t kClearAt = 22000;
  window(FaultKind::kDriverFault, kLatchAt);
  window(FaultKind::kEnableWriteFails, kLatchAt);
  mrd::control::SupervisorConfig limits;
  limits.driver_fault_window = 500;  // the spaced driver faults above must not latch
  mrd::telemetry::TelemetryQueue telemetry(1024);
  LoopRig rig(script, limits, &telemetry);
  auto stats = std::make_unique<mrd::runtime::LoopStatistics>();
  for (int i = 0; i < 10; ++i) rig.step();  // start-up

  std::uint64_t drained = 0;
  mrd::test::start_counting_allocations();
  for (int i = 10; i < 100000; ++i) {
    // Overruns: a burst of three lost periods every 20000 cycles, clear of the faults.
    const int skip = (i % 20000 == 19500 || i % 20000 == 19501 || i % 20000 == 19502) ? 1 : 0;
    if (i == kClearAt) rig.loop().request_clear_latch();
    rig.step(skip);
    stats->wake_latency.record(i);
    stats->execution.record(3 * i);
    stats->add_cycle(static_cast<std::uint64_t>(skip));
    if (i % 512 == 0) drained += telemetry.drain([](const mrd::telemetry::TelemetryRecord&) {});
  }
  const auto allocations = mrd::test::stop_counting_allocations();
  EXPECT_EQ(allocations, 0u);

  // The run went through every state and every fault trigger, or the zero proves little.
  const auto& t = rig.loop().supervisor().transitions();
  // SAFE: fifteen faults less the lost samples (they only degrade), twice for the heartbeat
  // (SAFE toggles none, so it recovers within its window and trips again), the latched driver
  // fault, and five overrun bursts.
  EXPECT_EQ(t.into(SupervisorState::kSafe), 21u);
  // DEGRADED first: the faults that are not immediate, and each overrun burst.
  EXPECT_EQ(t.into(SupervisorState::kDegraded), 18u);
  // RUN: start-up, after each SAFE but the latched one's, after the clear.
  EXPECT_EQ(t.into(SupervisorState::kRun), 23u);
  using mrd::control::Trigger;
  for (auto trig : {Trigger::kSensorStale, Trigger::kSampleNotFinite, Trigger::kSampleOutOfRange,
                    Trigger::kSampleCorrupted, Trigger::kDriverFault, Trigger::kFaultLineUnreadable,
                    Trigger::kCurrentDisagreement, Trigger::kSetpointWriteFailed, Trigger::kReadbackLost,
                    Trigger::kSetpointRefused, Trigger::kLineWriteFailed, Trigger::kSampleJump,
                    Trigger::kSampleFromFuture, Trigger::kRepeatedOverruns}) {
    std::uint64_t n = 0;
    for (auto from : {SupervisorState::kRun, SupervisorState::kDegraded}) {
      n += t.get(from, SupervisorState::kSafe, trig);
    }
    EXPECT_GE(n, 1u) << to_string(trig);
  }
  EXPECT_EQ(t.get(SupervisorState::kSafe, SupervisorState::kSafe, Trigger::kDisableFailed), 1u);
  EXPECT_EQ(t.get(SupervisorState::kSafe, SupervisorState::kSafe, Trigger::kOperatorClear), 1u);
  EXPECT_GT(drained, 90000u);
}

TEST(RealTime, ANonFiniteCommandsVetoDoesNotAllocate) {
  mrd::control::ControlLawConfig law;
  // A corrupted schedule through the uncompensated path: the slew limiter passes the NaN on.
  law.compensate_hysteresis = false;
  law.schedule.currents.fill(std::numeric_limits<double>::quiet_NaN());
  LoopRig rig({}, {}, nullptr, law);
  for (int i = 0; i < 10; ++i) rig.step();
  mrd::test::start_counting_allocations();
  for (int i = 10; i < 2000; ++i) rig.step();
  EXPECT_EQ(mrd::test::stop_counting_allocations(), 0u);
  EXPECT_GE(rig.loop().supervisor().transitions().get(SupervisorState::kRun, SupervisorState::kSafe,
                                                      mrd::control::Trigger::kCommandNotFinite),
            1u);
}

}  // namespace

namespace {

TEST(RealTime, ForceModeCycleDoesNotAllocateOnAnyDemandFaultPath) {
  // The force-mode law every period in RUN, and each demand fault through DEGRADED, SAFE and
  // recovery, with telemetry into the ring.
  FaultScript script;
  std::int64_t at = 1000;
  for (auto [kind, parameter] : {std::pair{FaultKind::kDemandMissing, 0.0}, std::pair{FaultKind::kDemandStale, 0.0},
                                 std::pair{FaultKind::kDemandNotFinite, 0.0},
                                 std::pair{FaultKind::kDemandOutOfRange, 1e6}}) {
    script.add({kind, cycle_time(at, LoopRig::kPeriod), cycle_time(at + 400, LoopRig::kPeriod), parameter});
    at += 1000;
  }
  mrd::telemetry::TelemetryQueue telemetry(1024);
  LoopRig rig(script, {}, &telemetry, mrd::test::force_law());
  for (int i = 0; i < 10; ++i) rig.step();
  std::uint64_t drained = 0;
  mrd::test::start_counting_allocations();
  for (int i = 10; i < 6000; ++i) {
    rig.step();
    if (i % 512 == 0) drained += telemetry.drain([](const mrd::telemetry::TelemetryRecord&) {});
  }
  EXPECT_EQ(mrd::test::stop_counting_allocations(), 0u);
  const auto& t = rig.loop().supervisor().transitions();
  using mrd::control::Trigger;
  EXPECT_EQ(t.get(SupervisorState::kDegraded, SupervisorState::kSafe, Trigger::kDemandStale), 2u);
  EXPECT_EQ(t.get(SupervisorState::kDegraded, SupervisorState::kSafe, Trigger::kDemandNotFinite), 1u);
  EXPECT_EQ(t.get(SupervisorState::kDegraded, SupervisorState::kSafe, Trigger::kDemandOutOfRange), 1u);
  EXPECT_EQ(t.into(SupervisorState::kRun), 5u) << "start-up and after each fault";
  EXPECT_GT(drained, 5000u);
}

TEST(RealTime, ForceModeLoadCellCorrectionDoesNotAllocateMovingFrozenOrAtItsBound) {
  // The load-cell correction every period in RUN: moving, at its bound, frozen while the load
  // cell is silent (stale) and while it reports a fault (bad), with telemetry into the ring.
  mrd::telemetry::TelemetryQueue telemetry(1024);
  LoopRig rig({}, {}, &telemetry, mrd::test::force_law_with_load_cell(0.2));
  rig.set_load_cell_gain(0.5);  // far below the model: the scale runs to its lower bound
  for (int i = 0; i < 10; ++i) rig.step();
  std::uint64_t drained = 0;
  mrd::test::start_counting_allocations();
  for (int i = 10; i < 6000; ++i) {
    rig.hal().load_cell.set_silent(i >= 3000 && i < 3500);
    rig.hal().load_cell.set_faulty(i >= 4000 && i < 4500);
    rig.step();
    if (i % 512 == 0) drained += telemetry.drain([](const mrd::telemetry::TelemetryRecord&) {});
  }
  EXPECT_EQ(mrd::test::stop_counting_allocations(), 0u);
  const auto* correction = rig.loop().law().force_scale_correction();
  ASSERT_NE(correction, nullptr);
  EXPECT_TRUE(correction->at_bound());
  EXPECT_GT(correction->stale_periods(), 400u);
  EXPECT_GT(correction->bad_samples(), 400u);
  EXPECT_EQ(rig.loop().state(), SupervisorState::kRun) << "a stale or bad load cell is not a fault";
  EXPECT_GT(drained, 5000u);
}

}  // namespace
