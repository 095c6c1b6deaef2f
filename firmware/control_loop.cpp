#include "firmware/control_loop.hpp"

#include <chrono>
#include <cmath>
#include <limits>

namespace mrd::firmware {

namespace {
// Telemetry's law_current and target_B while the supervisor drives the coil itself.
constexpr double kNotComputed = std::numeric_limits<double>::quiet_NaN();

hal::Timestamp to_period(double seconds) {
  return std::chrono::duration_cast<hal::Timestamp>(std::chrono::duration<double>(seconds));
}
}  // namespace

ControlLoop::ControlLoop(const control::ControlLawConfig& law, const control::SupervisorConfig& safety,
                         HalDevices devices, runtime::TelemetryQueue* telemetry, int telemetry_decimation)
    : law_(law),
      supervisor_(safety),
      checker_(safety.displacement_min, safety.displacement_max,
               safety.stale_periods * to_period(law.observer.sample_period), safety.frozen_periods),
      hal_(devices),
      telemetry_(telemetry),
      decimation_(telemetry_decimation > 0 ? static_cast<std::uint64_t>(telemetry_decimation) : 1u),
      period_(to_period(law.observer.sample_period)),
      fail_safe_current_(safety.fail_safe_current),
      current_tolerance_(safety.current_tolerance) {
  law_.hold(fail_safe_current_);
}

std::uint32_t ControlLoop::skipped_periods(hal::Timestamp now) const {
  if (cycles_ == 0 || now - last_release_ <= period_) return 0;
  // Releases are whole periods apart; anything short of the next one is wake-up jitter.
  const auto periods = (now - last_release_ + period_ / 2) / period_;
  return periods > 1 ? static_cast<std::uint32_t>(periods - 1) : 0u;
}

const runtime::TelemetryRecord& ControlLoop::step(hal::Timestamp now) {
  const std::uint32_t skipped = skipped_periods(now);
  overruns_ += skipped;
  last_release_ = now;

  // 1-2. The newest sample, judged.
  const control::SampleCheck check = checker_.check(hal_.lvdt.latest(), now);
  const std::optional<bool> fault = hal_.lines.driver_fault();
  const std::optional<hal::CurrentReading> measured = hal_.driver.measured();
  double coil = last_setpoint_;
  bool disagrees = false;
  if (measured) {
    disagrees = !std::isfinite(measured->value) ||
                std::fabs(measured->value - last_setpoint_) > current_tolerance_;
    if (std::isfinite(measured->value)) coil = measured->value;
  }

  // 3. Schedule and observer, on the last good displacement, whoever drives the coil.
  const control::ControlLaw::Observation& seen = law_.observe(
      {.displacement = checker_.held_value(), .timing = checker_.timing(check, now), .coil_current = coil});

  // 4. The supervisor.
  const control::SupervisorDecision d =
      supervisor_.step({check, fault, disagrees, write_failed_, skipped}, now);

  // 5. The compensated command, only while the law drives the coil.
  control::ControlLaw::Command command{kNotComputed, kNotComputed};
  if (d.in_control) {
    command = law_.command();
  } else {
    law_.hold(fail_safe_current_);
  }
  const double setpoint = d.in_control ? command.current : fail_safe_current_;

  // 6. Setpoint and lines.
  write_outputs(d, setpoint);

  // 7. Telemetry.
  record_ = runtime::TelemetryRecord{cycles_,
                            now,
                            checker_.held_value(),
                            measured ? measured->value : std::numeric_limits<double>::quiet_NaN(),
                            seen.scheduled_current,
                            command.current,
                            setpoint,
                            command.target_B,
                            seen.estimate.B,
                            seen.estimate.velocity,
                            seen.estimate.force,
                            skipped,
                            static_cast<std::uint8_t>(check),
                            static_cast<std::uint8_t>(d.state),
                            static_cast<std::uint8_t>(d.trigger),
                            d.enable};
  if (telemetry_ != nullptr && cycles_ % decimation_ == 0) telemetry_->offer(record_);
  ++cycles_;
  return record_;
}

void ControlLoop::write_outputs(const control::SupervisorDecision& d, double setpoint) {
  const hal::IoStatus written = hal_.driver.write_setpoint(setpoint);
  write_failed_ = written != hal::IoStatus::kOk;
  if (write_failed_) {
    ++failed_setpoint_writes_;
  } else {
    last_setpoint_ = setpoint;
  }
  // The enable line is written when it changes, and again after a failed write.
  if (!enable_written_ || d.enable != enable_) {
    enable_written_ = hal_.lines.set_enable(d.enable) == hal::IoStatus::kOk;
    if (!enable_written_) ++failed_line_writes_;
    enable_ = d.enable;
  }
  if (d.toggle_heartbeat && hal_.lines.toggle_heartbeat() != hal::IoStatus::kOk) {
    ++failed_line_writes_;
  }
}

}  // namespace mrd::firmware
