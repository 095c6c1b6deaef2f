#pragma once

#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>

#include <gtest/gtest.h>

#include "firmware/control_loop.hpp"
#include "hal/mock/mock_hal.hpp"

namespace mrd::test {

// A ControlLoop on the MockHal, one cycle per call, time driven by hand. The LVDT follows a
// 0.5 Hz, +-30 mm sine, so the schedule, observer and compensator all work every cycle; the
// force demand (force mode) is kDemandDamping times the sine's velocity.
class LoopRig {
 public:
  static constexpr hal::Timestamp kPeriod = std::chrono::milliseconds{1};
  static constexpr double kDemandDamping = 250e3;  // [N s/m]

  explicit LoopRig(hal::mock::FaultScript script = {}, control::SupervisorConfig safety = {},
                   telemetry::TelemetryQueue* telemetry = nullptr, const control::ControlLawConfig& law = {})
      : hal_(std::make_unique<hal::mock::MockHal>(std::move(script))),
        loop_(std::make_unique<firmware::ControlLoop>(
            law, safety,
            firmware::HalDevices{hal_->lvdt, hal_->driver, hal_->lines, &hal_->demand, &hal_->load_cell},
            telemetry)) {}

  // Runs cycle number `cycle_` at its release time; `skip` periods are lost before it.
  control::SupervisorState step(std::int64_t skip = 0) {
    cycle_ += skip;
    const hal::Timestamp now = hal::mock::cycle_time(cycle_, kPeriod);
    hal_->clock.set(now);
    const double w = 2.0 * std::numbers::pi * 0.5;
    const double t = std::chrono::duration<double>(now).count();
    hal_->lvdt.set_value(0.030 * std::sin(w * t));
    // Force mode's demand: a dissipative c v on the same motion (read in force mode only).
    hal_->demand.set_value(demand_damping_ * 0.030 * w * std::cos(w * t));
    // Force mode's load cell (read with a load-cell law only): load_cell_gain_ times the demand,
    // unless the test sets it itself.
    if (load_cell_gain_) hal_->load_cell.set_value(*load_cell_gain_ * demand_damping_ * 0.030 * w * std::cos(w * t));
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

  // The demand's coefficient from the next cycle on; negative asks the damper to push.
  void set_demand_damping(double c) { demand_damping_ = c; }
  // The load cell reads this share of the demand from the next cycle on: a damper that gives
  // `gain` of what is asked, whatever the current (1 by default).
  void set_load_cell_gain(double gain) { load_cell_gain_ = gain; }
  // The test sets hal().load_cell's force itself before each step.
  void set_load_cell_by_hand() { load_cell_gain_.reset(); }
  // The LVDT's true motion at time t [s] (displacement [m], velocity [m/s]).
  static double displacement_at(double t) { return 0.030 * std::sin(2.0 * std::numbers::pi * 0.5 * t); }
  static double velocity_at(double t) {
    return 0.030 * 2.0 * std::numbers::pi * 0.5 * std::cos(2.0 * std::numbers::pi * 0.5 * t);
  }
  [[nodiscard]] std::int64_t cycle() const { return cycle_; }  // the next cycle to run
  hal::mock::MockHal& hal() { return *hal_; }
  firmware::ControlLoop& loop() { return *loop_; }

 private:
  std::unique_ptr<hal::mock::MockHal> hal_;
  std::unique_ptr<firmware::ControlLoop> loop_;
  std::int64_t cycle_ = 0;
  double demand_damping_ = kDemandDamping;
  std::optional<double> load_cell_gain_ = 1.0;
};

// A fault scripted over cycles kFaultStart..kFaultEnd and the loop's reaction to it, in
// control periods (the "reaction" column of docs/FIRMWARE.md's transition table).
inline const control::SupervisorConfig kLimits{};  // the documented defaults

// The default law in force mode.
inline control::ControlLawConfig force_law() {
  control::ControlLawConfig law;
  law.mode = control::ControlMode::kForce;
  return law;
}

// The same with the load-cell correction on, its time constant `tau` [s].
inline control::ControlLawConfig force_law_with_load_cell(double tau = 1.0) {
  control::ControlLawConfig law = force_law();
  law.has_load_cell = true;
  law.load_cell.time_constant = tau;
  return law;
}
constexpr std::int64_t kFaultStart = 1000;
constexpr std::int64_t kFaultEnd = 1050;

inline hal::mock::FaultScript script_of(hal::mock::FaultKind kind, double parameter = 0.0) {
  return hal::mock::FaultScript{{kind, hal::mock::cycle_time(kFaultStart, LoopRig::kPeriod),
                      hal::mock::cycle_time(kFaultEnd, LoopRig::kPeriod), parameter}};
}

// What one fault does: the cycle it first shows DEGRADED (or -1), the cycle it reaches SAFE,
// and the cycle it is back in RUN.
struct Reaction {
  std::int64_t degraded = -1;
  std::int64_t safe = -1;
  std::int64_t run_again = -1;
};

inline Reaction react(LoopRig& rig) {
  rig.run_to(kFaultStart);
  EXPECT_EQ(rig.loop().state(), control::SupervisorState::kRun) << "the rig must be running when the fault starts";
  Reaction r;
  for (std::int64_t i = 0; i < 5000 && r.run_again < 0; ++i) {
    const auto s = rig.step();
    const auto at = rig.cycle() - 1;
    if (s == control::SupervisorState::kDegraded && r.degraded < 0 && r.safe < 0) r.degraded = at;
    if (s == control::SupervisorState::kSafe && r.safe < 0) r.safe = at;
    if (s == control::SupervisorState::kRun && r.safe >= 0) r.run_again = at;
  }
  return r;
}

// Recovery: RUN after recovery_periods good periods counted from the first period without the
// fault. A fault window ends at kFaultEnd; `first_good` may be later (a fault seen late).
inline void expect_recovery(const Reaction& r, std::int64_t first_good = kFaultEnd) {
  EXPECT_EQ(r.run_again, first_good + kLimits.recovery_periods - 1);
}

// What the reaction tests say, by its short name.
namespace reaction_terms {
using control::SupervisorConfig;
using control::SupervisorState;
using control::Trigger;
using hal::mock::FaultKind;
using hal::mock::FaultScript;
using hal::mock::cycle_time;
using test::LoopRig;
using test::Reaction;
using test::expect_recovery;
using test::kFaultEnd;
using test::kFaultStart;
using test::kLimits;
using test::react;
using test::script_of;
inline constexpr auto kInit = SupervisorState::kInit;
inline constexpr auto kRun = SupervisorState::kRun;
inline constexpr auto kDegraded = SupervisorState::kDegraded;
inline constexpr auto kSafe = SupervisorState::kSafe;
}  // namespace reaction_terms

}  // namespace mrd::test
