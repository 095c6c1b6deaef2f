// Zero heap allocations per cycle over 1e5 cycles after start-up, through every supervisor path:
// each fault kind of the mock HAL, overruns, SAFE and recovery, with telemetry into the ring.
#include <gtest/gtest.h>

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
                                 std::pair{FaultKind::kDriverWriteFails, 0.0}}) {
    window(kind, at, parameter);
    at += 1000;
  }
  mrd::runtime::TelemetryQueue telemetry(1024);
  LoopRig rig(script, {}, &telemetry);
  auto stats = std::make_unique<mrd::runtime::LoopStatistics>();
  for (int i = 0; i < 10; ++i) rig.step();  // start-up

  std::uint64_t drained = 0;
  mrd::test::start_counting_allocations();
  for (int i = 10; i < 100000; ++i) {
    // Overruns: a burst of three lost periods every 20000 cycles.
    const int skip = (i % 20000 == 15000 || i % 20000 == 15001 || i % 20000 == 15002) ? 1 : 0;
    rig.step(skip);
    stats->wake_latency.record(i);
    stats->execution.record(3 * i);
    stats->add_cycle(static_cast<std::uint64_t>(skip));
    if (i % 512 == 0) drained += telemetry.drain([](const mrd::runtime::TelemetryRecord&) {});
  }
  const auto allocations = mrd::test::stop_counting_allocations();
  EXPECT_EQ(allocations, 0u);

  // The run went through every state and every fault trigger, or the zero proves little.
  const auto& t = rig.loop().supervisor().transitions();
  // SAFE: nine faults (a lost sample in two only degrades) and five overrun bursts.
  EXPECT_EQ(t.into(SupervisorState::kSafe), 14u);
  // DEGRADED first: the eight faults that are not immediate, and each overrun burst.
  EXPECT_EQ(t.into(SupervisorState::kDegraded), 13u);
  // RUN: start-up, after each of the ten faults, after each burst.
  EXPECT_EQ(t.into(SupervisorState::kRun), 16u);
  for (auto trig : {mrd::control::Trigger::kSensorStale, mrd::control::Trigger::kSampleNotFinite,
                    mrd::control::Trigger::kSampleOutOfRange, mrd::control::Trigger::kSampleCorrupted,
                    mrd::control::Trigger::kDriverFault, mrd::control::Trigger::kFaultLineUnreadable,
                    mrd::control::Trigger::kCurrentDisagreement,
                    mrd::control::Trigger::kSetpointWriteFailed,
                    mrd::control::Trigger::kRepeatedOverruns}) {
    std::uint64_t n = 0;
    for (auto from : {SupervisorState::kRun, SupervisorState::kDegraded}) {
      n += t.get(from, SupervisorState::kSafe, trig);
    }
    EXPECT_GE(n, 1u) << to_string(trig);
  }
  EXPECT_GT(drained, 90000u);
}

}  // namespace
