#include "firmware/control_loop.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mrd::firmware {

namespace {
// Telemetry's law_current and target_B while the supervisor drives the coil itself.
constexpr double kNotComputed = std::numeric_limits<double>::quiet_NaN();

hal::Timestamp to_period(double seconds) {
  return std::chrono::duration_cast<hal::Timestamp>(std::chrono::duration<double>(seconds));
}

// Periods the load cell was stale or bad so far, saturated (0 without a correction).
std::uint32_t load_cell_frozen(const control::ForceScaleCorrection* correction) {
  if (correction == nullptr) return 0;
  const std::uint64_t n = correction->stale_periods() + correction->bad_samples();
  return static_cast<std::uint32_t>(std::min<std::uint64_t>(n, std::numeric_limits<std::uint32_t>::max()));
}
}  // namespace

ControlLoop::ControlLoop(const control::ControlLawConfig& law, const control::SupervisorConfig& safety,
                         HalDevices devices, telemetry::TelemetryQueue* telemetry, int telemetry_decimation)
    : law_(law),
      supervisor_(safety),
      checker_({.min = safety.displacement_min,
                .max = safety.displacement_max,
                .max_age = safety.stale_periods * to_period(law.observer.sample_period),
                .frozen_periods = safety.frozen_periods,
                .max_speed = safety.max_speed}),
      demand_checker_({.range = safety.demand_range,
                       .max_age = safety.demand_stale_periods * to_period(law.observer.sample_period)}),
      hal_(devices),
      bus_(devices.io_threads),
      telemetry_(telemetry),
      decimation_(telemetry_decimation > 0 ? static_cast<std::uint64_t>(telemetry_decimation) : 1u),
      period_(to_period(law.observer.sample_period)),
      fail_safe_current_(safety.fail_safe_current),
      current_tolerance_(safety.current_tolerance),
      readback_timeout_(safety.readback_timeout_periods * to_period(law.observer.sample_period)),
      require_readback_(safety.require_readback) {
  if (law.mode == control::ControlMode::kForce && hal_.demand == nullptr) {
    throw std::invalid_argument("control.mode = \"force\" needs a demand source");
  }
  if (law.mode == control::ControlMode::kForce && law.has_load_cell && hal_.load_cell == nullptr) {
    throw std::invalid_argument("the load-cell correction needs a load-cell source");
  }
  law_.hold(fail_safe_current_);
}

std::uint32_t ControlLoop::skipped_periods(hal::Timestamp now) const {
  if (cycles_ == 0 || now - last_release_ <= period_) return 0;
  // Releases are whole periods apart; anything short of the next one is wake-up jitter.
  const auto periods = (now - last_release_ + period_ / 2) / period_;
  // Saturated: a clock jump of 2^32 periods must not wrap to "no overrun".
  constexpr auto kMax = static_cast<std::int64_t>(std::numeric_limits<std::uint32_t>::max());
  return periods > 1 ? static_cast<std::uint32_t>(std::min<std::int64_t>(periods - 1, kMax)) : 0u;
}

// A driver that stops reporting its current reads as nullopt, which alone says nothing (a
// bus delivers readings slower than the loop runs): judged by the age of the newest one.
bool ControlLoop::readback_lost(const std::optional<hal::CurrentReading>& measured, hal::Timestamp now) {
  if (cycles_ == 0) started_ = now;
  if (measured) last_reading_ = now;
  if (readback_timeout_ <= hal::Timestamp{}) return false;
  if (last_reading_) return now - *last_reading_ > readback_timeout_;
  return require_readback_ && now - started_ > readback_timeout_;
}

control::LoadCellStatus ControlLoop::read_load_cell(double& newtons) {
  if (hal_.load_cell == nullptr) return control::LoadCellStatus::kNone;
  const std::optional<hal::Sample> s = hal_.load_cell->latest();
  if (!s || s->sequence == load_cell_sequence_) return control::LoadCellStatus::kNone;
  load_cell_sequence_ = s->sequence;
  if (!s->usable() || !std::isfinite(s->value)) return control::LoadCellStatus::kBad;
  newtons = s->value;
  return control::LoadCellStatus::kFresh;
}

const telemetry::TelemetryRecord& ControlLoop::step(hal::Timestamp now) {
  const std::uint32_t skipped = skipped_periods(now);
  overruns_ += skipped;
  last_release_ = now;
  if (clear_requested_.exchange(false, std::memory_order_relaxed)) supervisor_.clear_latch(now);

  const PeriodInputs in = read_inputs(now, skipped);
  // 3. Schedule and observer, on the last good displacement, whoever drives the coil.
  const control::ControlLaw::Observation& seen = law_.observe(
      {.displacement = checker_.held_value(), .timing = checker_.timing(in.sample, now), .coil_current = in.coil_current});
  control::SupervisorDecision d = supervise(in);
  const control::ControlLaw::Command command = compensate(in, d);
  const double setpoint = d.in_control ? command.current : fail_safe_current_;
  write_outputs(d, setpoint, now);
  publish_telemetry(in, seen, command, d, setpoint);
  ++cycles_;
  return record_;
}

// 1-2. The newest samples, judged, and what the driver reports.
ControlLoop::PeriodInputs ControlLoop::read_inputs(hal::Timestamp now, std::uint32_t skipped) {
  PeriodInputs in{.now = now, .skipped = skipped};
  in.sample = checker_.check(hal_.lvdt.latest(), now);
  in.demand = force_mode() ? demand_checker_.check(hal_.demand->latest(), now) : control::SampleCheck::kFresh;
  in.load_cell = read_load_cell(in.load_cell_force);
  in.driver_fault = hal_.lines.driver_fault();
  in.measured = hal_.driver.measured();
  in.coil_current = last_setpoint_;
  if (in.measured) {
    in.current_disagrees = !std::isfinite(in.measured->value) ||
                           std::fabs(in.measured->value - last_setpoint_) > current_tolerance_;
    if (std::isfinite(in.measured->value)) in.coil_current = in.measured->value;
  }
  return in;
}

// 4. The supervisor, on this period's inputs and what the previous period's writes did.
control::SupervisorDecision ControlLoop::supervise(const PeriodInputs& in) {
  const bool stalled = bus_.stalled(in.now);
  bus_stalled_.store(stalled, std::memory_order_relaxed);
  const hal::SetpointAcks acks = hal_.driver.setpoint_acks();
  const std::uint64_t recoveries = law_.observer().magnetics().recoveries();
  const control::SupervisorDecision d = supervisor_.step(
      {.sample = in.sample,
       .demand = in.demand,
       .driver_fault = in.driver_fault,
       .current_disagrees = in.current_disagrees,
       .setpoint_write_failed = write_failed_,
       .link_down = link_down_,
       .setpoints_refused = static_cast<std::uint32_t>(std::min<std::uint64_t>(acks.refused - acks_.refused, 1u << 16)),
       .setpoint_accepted = acks.accepted != acks_.accepted,
       .readback_lost = readback_lost(in.measured, in.now),
       .line_write_failed = line_failed_,
       .disable_failed = disable_failed_,
       .observer_recovered = recoveries != recoveries_,
       .bus_stalled = stalled,
       .overruns = in.skipped},
      in.now);
  acks_ = acks;
  recoveries_ = recoveries;
  return d;
}

// 5. The compensated command, only while the law drives the coil, and only a finite one: a
// non-finite command is vetoed into `d`. Otherwise the law holds the fail-safe current.
control::ControlLaw::Command ControlLoop::compensate(const PeriodInputs& in, control::SupervisorDecision& d) {
  control::ControlLaw::Command command{.current = kNotComputed, .target_B = kNotComputed};
  if (d.in_control) {
    // The load cell corrects the model's yield force scale only while the law drives the coil,
    // and only against an estimate made on this period's fresh LVDT sample: on a held or
    // extrapolated displacement the model's force is not the damper's, and the scale would
    // learn the sensor's fault.
    law_.correct_force_scale(in.sample == control::SampleCheck::kFresh ? in.load_cell : control::LoadCellStatus::kNone,
                             in.load_cell_force);
    command = law_.command(held_demand());
    // A non-finite target is control lost as surely as a non-finite current (a finite 0 A beside
    // target_B = NaN drives nothing): the same veto. The observer's J-A state resets itself
    // (observer_recovered above).
    if (!std::isfinite(command.current) || !std::isfinite(command.target_B)) {
      d = supervisor_.veto(control::Trigger::kCommandNotFinite, in.now);
    }
  }
  if (!d.in_control) law_.hold(fail_safe_current_);
  return command;
}

// Force mode's demand: the last good one, held while demands are missing or bad.
double ControlLoop::held_demand() const { return force_mode() ? demand_checker_.held_value() : kNotComputed; }

// 7. The period's record, into the ring every `decimation_` cycles.
void ControlLoop::publish_telemetry(const PeriodInputs& in, const control::ControlLaw::Observation& seen,
                                    const control::ControlLaw::Command& command, const control::SupervisorDecision& d,
                                    double setpoint) {
  const control::ForceScaleCorrection* correction = law_.force_scale_correction();
  // By name: a positional list of twelve doubles would compile with two of them swapped.
  record_ = telemetry::TelemetryRecord{
      .cycle = cycles_,
      .time = in.now,
      .displacement = checker_.held_value(),
      .measured_current = in.measured ? in.measured->value : std::numeric_limits<double>::quiet_NaN(),
      .scheduled_current = seen.scheduled_current,
      .law_current = command.current,
      .setpoint = setpoint,
      .target_B = command.target_B,
      .B = seen.estimate.B,
      .velocity = seen.estimate.velocity,
      .force = seen.estimate.force,
      .overruns = in.skipped,
      .sample = static_cast<std::uint8_t>(in.sample),
      .state = static_cast<std::uint8_t>(d.state),
      .trigger = static_cast<std::uint8_t>(d.trigger),
      .enable = d.enable,
      .latched = d.latched,
      .recoveries = recoveries_,
      .demand = held_demand(),
      .yield_force = command.yield_force,
      .demand_check = static_cast<std::uint8_t>(in.demand),
      .clipped = command.clipped,
      .reached = command.reached,
      .force_scale = force_mode() ? law_.force_scale() : kNotComputed,
      .load_cell_frozen = load_cell_frozen(correction),
      .force_scale_at_bound = d.in_control && correction != nullptr && correction->reached_bound()};
  if (telemetry_ != nullptr && cycles_ % decimation_ == 0) telemetry_->offer(record_);
}

// 6. The setpoint and the lines.
void ControlLoop::write_outputs(const control::SupervisorDecision& d, double setpoint, hal::Timestamp now) {
  const hal::IoStatus written = hal_.driver.write_setpoint(setpoint);
  const bool queued = written == hal::IoStatus::kOk;
  // Queued is not delivered: a bus thread that stopped taking them fails the write too.
  const bool undelivered = bus_.undelivered(hal_.driver.handover(), queued, now);
  write_failed_ = !queued || undelivered;
  link_down_ = written == hal::IoStatus::kNotConnected;
  if (write_failed_) {
    ++failed_setpoint_writes_;
  } else {
    last_setpoint_ = setpoint;
  }
  // The enable line is written when it changes, and again after a failed write.
  line_failed_ = false;
  disable_failed_ = false;
  if (!enable_written_ || d.enable != enable_) {
    enable_written_ = hal_.lines.set_enable(d.enable) == hal::IoStatus::kOk;
    line_failed_ = !enable_written_;
    disable_failed_ = !enable_written_ && !d.enable;
    enable_ = d.enable;
  }
  if (d.toggle_heartbeat && hal_.lines.toggle_heartbeat() != hal::IoStatus::kOk) line_failed_ = true;
  if (line_failed_) ++failed_line_writes_;
}

}  // namespace mrd::firmware
