// Bus-thread liveness and delivery through the whole loop: a bus thread the test steps by hand
// (a driver whose setpoints it takes, an un-started IoThread whose progress it beats). A thread
// that stops taking setpoints fails the writes; one that stops making progress is SAFE with the
// enable line off, even where SAFE keeps it on. Time is the loop's release time; nothing sleeps.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>

#include "firmware/control_loop.hpp"
#include "hal/io_thread.hpp"
#include "hal/mock/mock_hal.hpp"

namespace {

using namespace std::chrono_literals;
using mrd::control::SupervisorState;
using mrd::control::Trigger;
using mrd::hal::Timestamp;

// write_setpoint queues for a bus thread, as the Modbus back end's mailbox does, and reports kOk
// (linked); take() is one pass of that thread.
class SteppedBusDriver final : public mrd::hal::CurrentDriver {
 public:
  static constexpr Timestamp kWithin = 5ms;
  mrd::hal::IoStatus write_setpoint(double amps) override {
    queued_ = amps;
    return mrd::hal::IoStatus::kOk;
  }
  std::optional<mrd::hal::CurrentReading> measured() override { return std::nullopt; }
  [[nodiscard]] std::optional<mrd::hal::SetpointHandover> handover() const override {
    return mrd::hal::SetpointHandover{taken_, kWithin};
  }
  void take() {
    if (!queued_) return;
    delivered_ = *queued_;
    queued_.reset();
    ++taken_;
  }
  [[nodiscard]] double delivered() const { return delivered_; }

 private:
  std::optional<double> queued_;
  double delivered_ = 0.0;
  std::uint64_t taken_ = 0;
};

struct BusRig {
  static constexpr Timestamp kPeriod = 1ms;
  explicit BusRig(const mrd::control::SupervisorConfig& safety = quick()) : loop(law(), safety, devices()) {
    thread.set_max_silence(10ms);
  }
  static mrd::control::SupervisorConfig quick() {
    mrd::control::SupervisorConfig s;
    s.recovery_periods = 20;
    return s;
  }
  static mrd::control::ControlLawConfig law() { return {}; }
  mrd::firmware::HalDevices devices() { return {hal.lvdt, driver, hal.lines, nullptr, nullptr, threads}; }

  // One cycle; the bus thread takes (after the write) and beats as told.
  SupervisorState step(bool takes = true, bool beats = true) {
    const Timestamp now = cycle * kPeriod;
    hal.clock.set(now);
    hal.lvdt.set_value(0.030 * std::sin(std::numbers::pi * std::chrono::duration<double>(now).count()));
    loop.step(now);
    if (takes) driver.take();
    if (beats) thread.beat();
    ++cycle;
    return loop.state();
  }
  std::int64_t run_until(SupervisorState s, bool takes = true, bool beats = true) {
    for (int i = 0; i < 10000; ++i) {
      if (step(takes, beats) == s) return cycle - 1;
    }
    return -1;
  }

  mrd::hal::mock::MockHal hal;
  SteppedBusDriver driver;
  mrd::hal::IoThread thread;
  std::array<mrd::hal::IoThread*, 1> threads{&thread};
  mrd::firmware::ControlLoop loop;
  std::int64_t cycle = 0;
};

TEST(BusLiveness, ALiveBusThreadRunsWithoutFailures) {
  BusRig rig;
  ASSERT_GE(rig.run_until(SupervisorState::kRun), 0);
  for (int i = 0; i < 200; ++i) ASSERT_EQ(rig.step(), SupervisorState::kRun);
  EXPECT_EQ(rig.loop.failed_setpoint_writes(), 0u);
  EXPECT_FALSE(rig.loop.bus_stalled());
  EXPECT_EQ(rig.driver.delivered(), rig.loop.last().setpoint);
}

// Writes report kOk into the mailbox, but the thread (still beating) takes none: each write
// past the handover's 5 ms fails, DEGRADED, then SAFE after write_failure_periods.
TEST(BusLiveness, SetpointsNotTakenWithinTheHandoverAreFailedWrites) {
  BusRig rig;
  ASSERT_GE(rig.run_until(SupervisorState::kRun), 0);
  const std::int64_t stop = rig.cycle;
  // Cycles stop..stop+5 wait 0..5 ms: not over the handover yet.
  for (int i = 0; i <= 5; ++i) ASSERT_EQ(rig.step(false), SupervisorState::kRun) << i;
  // Cycle stop+6's write waited 6 ms: failed, judged the period after.
  EXPECT_EQ(rig.step(false), SupervisorState::kRun);
  EXPECT_EQ(rig.step(false), SupervisorState::kDegraded);
  EXPECT_EQ(static_cast<Trigger>(rig.loop.last().trigger), Trigger::kSetpointWriteFailed);
  const std::int64_t safe = rig.run_until(SupervisorState::kSafe, false);
  EXPECT_EQ(safe, stop + 7 + rig.loop.supervisor().config().write_failure_periods - 1);
  EXPECT_EQ(static_cast<Trigger>(rig.loop.last().trigger), Trigger::kSetpointWriteFailed);
  EXPECT_FALSE(rig.loop.bus_stalled());
  // Taking again: RUN after recovery_periods good periods.
  EXPECT_GE(rig.run_until(SupervisorState::kRun), 0);
}

// The thread stops making progress: SAFE (bus_stalled) in the first period past its
// max_silence, enable off although enable_in_safe keeps it on in any other SAFE, and the
// watchdog's feeder told; once it moves again, RUN after recovery_periods.
TEST(BusLiveness, AStalledBusThreadIsSafeWithTheEnableLineOff) {
  mrd::control::SupervisorConfig safety = BusRig::quick();
  safety.enable_in_safe = true;
  BusRig rig(safety);
  EXPECT_EQ(rig.step(), SupervisorState::kInit);
  EXPECT_TRUE(rig.hal.lines.enabled());  // enable_in_safe
  ASSERT_GE(rig.run_until(SupervisorState::kRun), 0);
  const std::int64_t last_beat = rig.cycle - 1;
  // Progress seen at last_beat + 1 stands until last_beat + 11, 10 ms later: not over yet.
  for (int i = 0; i <= 10; ++i) ASSERT_NE(rig.step(true, false), SupervisorState::kSafe) << i;
  EXPECT_EQ(rig.step(true, false), SupervisorState::kSafe);
  EXPECT_EQ(rig.cycle - 1, last_beat + 12);
  EXPECT_EQ(static_cast<Trigger>(rig.loop.last().trigger), Trigger::kBusStalled);
  EXPECT_FALSE(rig.hal.lines.enabled());
  EXPECT_TRUE(rig.loop.bus_stalled());
  for (int i = 0; i < 50; ++i) {
    ASSERT_EQ(rig.step(true, false), SupervisorState::kSafe);
    ASSERT_FALSE(rig.hal.lines.enabled());
  }
  // It moves again: enable back on in SAFE at once, RUN after recovery_periods.
  EXPECT_EQ(rig.step(), SupervisorState::kSafe);
  EXPECT_EQ(rig.step(), SupervisorState::kSafe);
  EXPECT_FALSE(rig.loop.bus_stalled());
  EXPECT_TRUE(rig.hal.lines.enabled());
  const std::int64_t resumed = rig.cycle;
  EXPECT_EQ(rig.run_until(SupervisorState::kRun), resumed + safety.recovery_periods - 2);
  EXPECT_EQ(rig.loop.supervisor().transitions().get(SupervisorState::kRun, SupervisorState::kSafe,
                                                    Trigger::kBusStalled), 1u);
}

}  // namespace
