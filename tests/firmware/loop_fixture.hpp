#pragma once

#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>

#include "firmware/control_loop.hpp"
#include "hal/mock/mock_hal.hpp"

namespace mrd::test {

// A ControlLoop on the MockHal, one cycle per call, time driven by hand. The LVDT follows a
// 0.5 Hz, +-30 mm sine, so the schedule, observer and compensator all work every cycle.
class LoopRig {
 public:
  static constexpr hal::Timestamp kPeriod = std::chrono::milliseconds{1};

  explicit LoopRig(hal::mock::FaultScript script = {}, control::SupervisorConfig safety = {},
                   runtime::TelemetryQueue* telemetry = nullptr)
      : hal_(std::make_unique<hal::mock::MockHal>(std::move(script))),
        loop_(std::make_unique<firmware::ControlLoop>(
            control::ControlLawConfig{}, safety,
            firmware::HalDevices{hal_->lvdt, hal_->driver, hal_->lines}, telemetry)) {}

  // Runs cycle number `cycle_` at its release time; `skip` periods are lost before it.
  control::SupervisorState step(int skip = 0) {
    cycle_ += skip;
    const hal::Timestamp now = hal::mock::cycle_time(cycle_, kPeriod);
    hal_->clock.set(now);
    hal_->lvdt.set_truth(0.030 * std::sin(2.0 * std::numbers::pi * 0.5 * std::chrono::duration<double>(now).count()));
    loop_->step(now);
    ++cycle_;
    return loop_->state();
  }
  // Steps until `state` is reached (returns its cycle number) or `limit` cycles pass (-1).
  std::int64_t run_until(control::SupervisorState state, std::int64_t limit = 100000) {
    for (std::int64_t i = 0; i < limit; ++i) {
      if (step() == state) return cycle_ - 1;
    }
    return -1;
  }
  void run_to(std::int64_t cycle) {
    while (cycle_ < cycle) step();
  }

  [[nodiscard]] std::int64_t cycle() const { return cycle_; }  // the next cycle to run
  hal::mock::MockHal& hal() { return *hal_; }
  firmware::ControlLoop& loop() { return *loop_; }

 private:
  std::unique_ptr<hal::mock::MockHal> hal_;
  std::unique_ptr<firmware::ControlLoop> loop_;
  std::int64_t cycle_ = 0;
};

}  // namespace mrd::test
