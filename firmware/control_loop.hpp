#pragma once

#include <atomic>
#include <cstdint>
#include <optional>

#include "control/control_law.hpp"
#include "control/demand_check.hpp"
#include "firmware/bus_watch.hpp"
#include "firmware/hal_devices.hpp"
#include "control/sample_check.hpp"
#include "control/supervisor.hpp"
#include "telemetry/telemetry_queue.hpp"
#include "telemetry/telemetry_record.hpp"
#include "hal/clock.hpp"
#include "hal/status.hpp"

namespace mrd::firmware {

// One control cycle:
//   1. take the newest sample (and, in     5. only while in control, compensate the command
//      force mode, the newest demand);       (otherwise the law holds the fail-safe current);
//   2. check freshness and range;
//   3. apply the Table 4 schedule and     6. write the current setpoint and the lines;
//      run the observer;                  7. push a telemetry record into the lock-free ring.
//   4. let the supervisor decide;
// step(now) is the whole cycle. `now` is the cycle's release time: the real-time runner passes
// its deadline, tests pass a ManualClock's time. Periods skipped between two calls are the
// overruns the supervisor judges. No heap, no locks, no exceptions, no blocking I/O.
class ControlLoop {
 public:
  // The period is the control law's sample period. `telemetry` may be null (no telemetry).
  // Force mode needs `devices.demand`, and its load-cell correction `devices.load_cell`
  // (std::invalid_argument without them).
  ControlLoop(const control::ControlLawConfig& law, const control::SupervisorConfig& safety, HalDevices devices,
              telemetry::TelemetryQueue* telemetry = nullptr, int telemetry_decimation = 1);

  const telemetry::TelemetryRecord& step(hal::Timestamp now);
  // The next cycle goes to SAFE (fail-safe current, enable as configured) and stays there.
  void request_shutdown() { supervisor_.request_shutdown(); }
  // An operator's clear of a latched SAFE, taken at the next cycle; safe from any thread or a
  // signal handler.
  void request_clear_latch() { clear_requested_.store(true, std::memory_order_relaxed); }

  [[nodiscard]] const control::Supervisor& supervisor() const { return supervisor_; }
  [[nodiscard]] const control::ControlLaw& law() const { return law_; }
  [[nodiscard]] control::SupervisorState state() const { return supervisor_.state(); }
  [[nodiscard]] const telemetry::TelemetryRecord& last() const { return record_; }
  [[nodiscard]] std::uint64_t cycles() const { return cycles_; }
  [[nodiscard]] std::uint64_t overruns() const { return overruns_; }
  [[nodiscard]] std::uint64_t failed_setpoint_writes() const { return failed_setpoint_writes_; }
  [[nodiscard]] std::uint64_t failed_line_writes() const { return failed_line_writes_; }
  [[nodiscard]] hal::Timestamp period() const { return period_; }
  // A bus I/O thread stood still at the last cycle: safe from any thread (the watchdog's feeder).
  [[nodiscard]] bool bus_stalled() const { return bus_stalled_.load(std::memory_order_relaxed); }

 private:
  // What one period read, judged (steps 1-2), for the steps after it.
  struct PeriodInputs {
    hal::Timestamp now{};
    std::uint32_t skipped = 0;  // periods lost before this one
    control::SampleCheck sample = control::SampleCheck::kFresh;
    control::SampleCheck demand = control::SampleCheck::kFresh;  // kFresh in table4 mode
    control::LoadCellStatus load_cell = control::LoadCellStatus::kNone;
    double load_cell_force = 0.0;  // [N], when load_cell is kFresh
    std::optional<bool> driver_fault;
    std::optional<hal::CurrentReading> measured;
    double coil_current = 0.0;  // measured when finite, else the last accepted setpoint [A]
    bool current_disagrees = false;
  };

  // The cycle's steps, in order.
  PeriodInputs read_inputs(hal::Timestamp now, std::uint32_t skipped);
  control::SupervisorDecision supervise(const PeriodInputs& in);
  control::ControlLaw::Command compensate(const PeriodInputs& in, control::SupervisorDecision& d);
  void write_outputs(const control::SupervisorDecision& d, double setpoint, hal::Timestamp now);
  void publish_telemetry(const PeriodInputs& in, const control::ControlLaw::Observation& seen,
                         const control::ControlLaw::Command& command, const control::SupervisorDecision& d,
                         double setpoint);

  std::uint32_t skipped_periods(hal::Timestamp now) const;
  // Force mode's load cell this period: nothing new (also a repeated sample), a fresh usable
  // one (its value in `newtons`), or a bad one.
  control::LoadCellStatus read_load_cell(double& newtons);
  [[nodiscard]] bool readback_lost(const std::optional<hal::CurrentReading>& measured, hal::Timestamp now);
  [[nodiscard]] bool force_mode() const { return law_.mode() == control::ControlMode::kForce; }
  [[nodiscard]] double held_demand() const;

  control::ControlLaw law_;
  control::Supervisor supervisor_;
  control::SampleChecker checker_;
  control::DemandChecker demand_checker_;
  std::optional<std::uint32_t> load_cell_sequence_;  // the last load-cell sample's
  HalDevices hal_;
  BusWatch bus_;
  telemetry::TelemetryQueue* telemetry_;
  std::uint64_t decimation_;
  hal::Timestamp period_;
  double fail_safe_current_;
  double current_tolerance_;
  hal::Timestamp readback_timeout_;  // 0: no readback expected
  bool require_readback_;

  telemetry::TelemetryRecord record_;
  std::uint64_t cycles_ = 0;
  std::uint64_t overruns_ = 0;
  std::uint64_t failed_setpoint_writes_ = 0;
  std::uint64_t failed_line_writes_ = 0;
  hal::Timestamp last_release_{};
  double last_setpoint_ = 0.0;  // the last setpoint the driver accepted [A]
  bool write_failed_ = false;   // the previous period's write, judged this period
  bool link_down_ = false;      // ... and it failed for want of a link
  bool line_failed_ = false;    // the previous period's enable or heartbeat write
  bool disable_failed_ = false; // ... and it was the enable line going low
  bool enable_ = false;
  bool enable_written_ = false;
  hal::Timestamp started_{};
  std::optional<hal::Timestamp> last_reading_;  // when the newest measured current arrived
  hal::SetpointAcks acks_;                      // as of the previous period
  std::uint64_t recoveries_ = 0;                // the observer's, as of the previous period
  std::atomic<bool> clear_requested_{false};
  std::atomic<bool> bus_stalled_{false};
};

}  // namespace mrd::firmware
