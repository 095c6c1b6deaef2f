#include "control/supervisor.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

namespace mrd::control {

std::string_view to_string(SupervisorState s) {
  switch (s) {
    case SupervisorState::kInit: return "INIT";
    case SupervisorState::kRun: return "RUN";
    case SupervisorState::kDegraded: return "DEGRADED";
    case SupervisorState::kSafe: return "SAFE";
    case SupervisorState::kCount: break;
  }
  return "?";
}

std::string_view to_string(Trigger t) {
  switch (t) {
    case Trigger::kNone: return "none";
    case Trigger::kGoodPeriods: return "good_periods";
    case Trigger::kSampleMissing: return "sample_missing";
    case Trigger::kSensorStale: return "sensor_stale";
    case Trigger::kSampleOutOfRange: return "sample_out_of_range";
    case Trigger::kSampleNotFinite: return "sample_not_finite";
    case Trigger::kSampleCorrupted: return "sample_corrupted";
    case Trigger::kSampleFrozen: return "sample_frozen";
    case Trigger::kSampleJump: return "sample_jump";
    case Trigger::kSampleFromFuture: return "sample_from_future";
    case Trigger::kDriverFault: return "driver_fault";
    case Trigger::kFaultLineUnreadable: return "fault_line_unreadable";
    case Trigger::kCurrentDisagreement: return "current_disagreement";
    case Trigger::kSetpointWriteFailed: return "setpoint_write_failed";
    case Trigger::kSetpointRefused: return "setpoint_refused";
    case Trigger::kReadbackLost: return "readback_lost";
    case Trigger::kLineWriteFailed: return "line_write_failed";
    case Trigger::kDisableFailed: return "disable_failed";
    case Trigger::kObserverRecovery: return "observer_recovery";
    case Trigger::kCommandNotFinite: return "command_not_finite";
    case Trigger::kOverrun: return "overrun";
    case Trigger::kRepeatedOverruns: return "repeated_overruns";
    case Trigger::kShutdown: return "shutdown";
    case Trigger::kOperatorClear: return "operator_clear";
    case Trigger::kDemandMissing: return "demand_missing";
    case Trigger::kDemandStale: return "demand_stale";
    case Trigger::kDemandOutOfRange: return "demand_out_of_range";
    case Trigger::kDemandNotFinite: return "demand_not_finite";
    case Trigger::kDemandCorrupted: return "demand_corrupted";
    case Trigger::kDemandFromFuture: return "demand_from_future";
    case Trigger::kLinkTimeout: return "link_timeout";
    case Trigger::kBusStalled: return "bus_stalled";
    case Trigger::kCount: break;
  }
  return "?";
}

ValidationReport SupervisorConfig::validate() const {
  ValidationReport r;
  const auto at_least = [&r](std::string_view field, int value, int lo) {
    r.check(value >= lo, field, "must be >= " + std::to_string(lo) + ", got " + std::to_string(value));
  };
  if (r.check(std::isfinite(displacement_min) && std::isfinite(displacement_max), "displacement_min",
              "displacement_min and displacement_max must be finite")) {
    r.check(displacement_max > displacement_min, "displacement_max",
            "must be above displacement_min");
  }
  at_least("stale_periods", stale_periods, 1);
  at_least("bad_sample_periods", bad_sample_periods, 1);
  at_least("frozen_periods", frozen_periods, 0);
  r.check(std::isfinite(current_tolerance) && current_tolerance > 0.0, "current_tolerance",
          "must be a finite value > 0 A");
  at_least("current_disagreement_periods", current_disagreement_periods, 1);
  at_least("write_failure_periods", write_failure_periods, 1);
  at_least("readback_timeout_periods", readback_timeout_periods, 0);
  if (require_readback) {
    r.check(readback_timeout_periods > 0, "require_readback",
            "needs safety.readback_timeout_periods > 0 to know how long to wait");
  }
  at_least("line_failure_periods", line_failure_periods, 1);
  at_least("observer_recovery_periods", observer_recovery_periods, 1);
  r.check(std::isfinite(max_speed) && max_speed >= 0.0, "max_speed", "must be a finite value >= 0 m/s (0: off)");
  constexpr int kMaxLimit = static_cast<int>(Supervisor::kMaxDriverFaultLimit);
  r.check(driver_fault_limit >= 1 && driver_fault_limit <= kMaxLimit, "driver_fault_limit",
          "must be 1.." + std::to_string(kMaxLimit) + ", got " + std::to_string(driver_fault_limit));
  at_least("driver_fault_window", driver_fault_window, 1);
  at_least("overrun_limit", overrun_limit, 1);
  at_least("overrun_window", overrun_window, 1);
  r.check(std::isfinite(fail_safe_current), "fail_safe_current", "must be finite");
  if (!enable_in_safe) {
    r.check(fail_safe_current == 0.0, "fail_safe_current",
            "must be 0 A when safety.enable_in_safe is false: a disabled driver drives no current");
  }
  at_least("recovery_periods", recovery_periods, 1);
  at_least("degraded_clear_periods", degraded_clear_periods, 1);
  at_least("demand_stale_periods", demand_stale_periods, 1);
  r.check(std::isfinite(demand_range) && demand_range > 0.0, "demand_range", "must be a finite value > 0 N");
  // An hour bounds a typo (3600 periods meant as seconds), not a real device's boot.
  r.check(std::isfinite(link_timeout) && link_timeout > 0.0 && link_timeout <= 3600.0, "link_timeout",
          "must be a finite value in (0, 3600] s");
  return r;
}

Supervisor::Supervisor(const SupervisorConfig& config)
    : config_(config),
      // Clamped: an unvalidated value must not overflow the conversion.
      link_timeout_(std::chrono::duration_cast<hal::Timestamp>(
          std::chrono::duration<double>(std::isfinite(config.link_timeout)
                                            ? std::clamp(config.link_timeout, 0.0, 1e6) : 1e6))) {}

std::uint64_t TransitionCounts::total() const {
  std::uint64_t sum = 0;
  for (const auto& c : counts_) sum += c.get();
  return sum;
}

std::uint64_t TransitionCounts::into(SupervisorState to) const {
  std::uint64_t sum = 0;
  for (std::size_t from = 0; from < kStates; ++from) {
    if (static_cast<SupervisorState>(from) == to) continue;
    for (std::size_t why = 0; why < kTriggers; ++why) {
      sum += get(static_cast<SupervisorState>(from), to, static_cast<Trigger>(why));
    }
  }
  return sum;
}

namespace {
Trigger trigger_of(SampleCheck c) {
  switch (c) {
    case SampleCheck::kOutOfRange: return Trigger::kSampleOutOfRange;
    case SampleCheck::kNotFinite: return Trigger::kSampleNotFinite;
    case SampleCheck::kCorrupted: return Trigger::kSampleCorrupted;
    case SampleCheck::kFrozen: return Trigger::kSampleFrozen;
    case SampleCheck::kJump: return Trigger::kSampleJump;
    case SampleCheck::kFromFuture: return Trigger::kSampleFromFuture;
    case SampleCheck::kMissing:
    case SampleCheck::kStale: return Trigger::kSampleMissing;
    case SampleCheck::kFresh: break;
  }
  return Trigger::kNone;
}

// The same judgement of the force demand; the frozen and jump checks do not apply to it.
Trigger demand_trigger_of(SampleCheck c) {
  switch (c) {
    case SampleCheck::kOutOfRange: return Trigger::kDemandOutOfRange;
    case SampleCheck::kNotFinite: return Trigger::kDemandNotFinite;
    case SampleCheck::kCorrupted:
    case SampleCheck::kFrozen:
    case SampleCheck::kJump: return Trigger::kDemandCorrupted;
    case SampleCheck::kFromFuture: return Trigger::kDemandFromFuture;
    case SampleCheck::kMissing:
    case SampleCheck::kStale: return Trigger::kDemandMissing;
    case SampleCheck::kFresh: break;
  }
  return Trigger::kNone;
}

// SAFE entries that point at the driver or its wiring: repeated, they latch.
bool is_driver_side(Trigger t) {
  switch (t) {
    case Trigger::kDriverFault:
    case Trigger::kFaultLineUnreadable:
    case Trigger::kCurrentDisagreement:
    case Trigger::kSetpointWriteFailed:
    case Trigger::kSetpointRefused:
    case Trigger::kReadbackLost:
    case Trigger::kLineWriteFailed: return true;
    default: return false;
  }
}
}  // namespace

void Supervisor::update_counters(const SupervisorInputs& in) {
  const auto run = [](std::int64_t& counter, bool condition) { counter = condition ? counter + 1 : 0; };
  run(without_sample_, in.sample != SampleCheck::kFresh);
  run(bad_samples_, is_bad_value(in.sample));
  run(without_demand_, in.demand != SampleCheck::kFresh);
  run(bad_demands_, is_bad_value(in.demand));
  run(disagreeing_, in.current_disagrees);
  run(failed_writes_, in.setpoint_write_failed);
  run(failed_lines_, in.line_write_failed);
  run(failed_disables_, in.disable_failed);
  run(recovering_, in.observer_recovered);
  if (in.setpoints_refused > 0) {
    refused_ += in.setpoints_refused;
  } else if (in.setpoint_accepted) {
    refused_ = 0;
  }
  ++periods_;
  if (in.overruns > 0) {
    overruns_ += in.overruns;
    clean_periods_ = 0;
  } else if (++clean_periods_ >= config_.overrun_window) {
    overruns_ = 0;
  }
}

// SAFE triggers, in priority order: the first that holds names the transition.
Trigger Supervisor::hard_trigger(const SupervisorInputs& in) const {
  if (shutdown_) return Trigger::kShutdown;
  if (!in.driver_fault) return Trigger::kFaultLineUnreadable;
  if (*in.driver_fault) return Trigger::kDriverFault;
  if (in.bus_stalled) return Trigger::kBusStalled;
  if (bad_samples_ >= config_.bad_sample_periods) return trigger_of(in.sample);
  if (without_sample_ > config_.stale_periods) return Trigger::kSensorStale;
  if (bad_demands_ >= config_.bad_sample_periods) return demand_trigger_of(in.demand);
  if (without_demand_ > config_.demand_stale_periods) return Trigger::kDemandStale;
  if (disagreeing_ >= config_.current_disagreement_periods) return Trigger::kCurrentDisagreement;
  if (failed_writes_ >= config_.write_failure_periods) return Trigger::kSetpointWriteFailed;
  if (refused_ >= config_.write_failure_periods) return Trigger::kSetpointRefused;
  if (in.readback_lost) return Trigger::kReadbackLost;
  if (failed_lines_ >= config_.line_failure_periods) return Trigger::kLineWriteFailed;
  if (recovering_ >= config_.observer_recovery_periods) return Trigger::kObserverRecovery;
  if (overruns_ >= config_.overrun_limit) return Trigger::kRepeatedOverruns;
  return Trigger::kNone;
}

// DEGRADED triggers: a problem that has not lasted long enough for SAFE.
Trigger Supervisor::soft_trigger(const SupervisorInputs& in) const {
  if (in.sample != SampleCheck::kFresh) return trigger_of(in.sample);
  if (in.demand != SampleCheck::kFresh) return demand_trigger_of(in.demand);
  if (in.current_disagrees) return Trigger::kCurrentDisagreement;
  if (in.setpoint_write_failed) return Trigger::kSetpointWriteFailed;
  if (in.setpoints_refused > 0) return Trigger::kSetpointRefused;
  if (in.line_write_failed) return Trigger::kLineWriteFailed;
  if (in.observer_recovered) return Trigger::kObserverRecovery;
  if (in.overruns > 0) return Trigger::kOverrun;
  return Trigger::kNone;
}

void Supervisor::go(SupervisorState to, Trigger why, hal::Timestamp now, SupervisorDecision& d) {
  counts_.count(state_, to, why);
  state_ = to;
  since_ = now;
  d.trigger = why;
  if (to == SupervisorState::kSafe) {
    // SAFE is a clean start: recovery needs recovery_periods good periods from here, and an
    // overrun after it counts as the first again.
    good_ = 0;
    overruns_ = 0;
    if (is_driver_side(why)) count_driver_fault();
  }
}

// A driver that faults, recovers and faults again would cycle RUN <-> SAFE forever, each time
// driving the coil again: at driver_fault_limit entries within driver_fault_window periods,
// SAFE holds until an operator has looked.
void Supervisor::count_driver_fault() {
  const auto limit = static_cast<std::size_t>(config_.driver_fault_limit);
  driver_faults_[driver_fault_count_ % limit] = periods_;
  ++driver_fault_count_;
  if (driver_fault_count_ < limit) return;
  const std::int64_t oldest = driver_faults_[driver_fault_count_ % limit];
  if (periods_ - oldest < config_.driver_fault_window) latched_ = true;
}

void Supervisor::clear_latch(hal::Timestamp now) {
  if (!latched_) return;
  latched_ = false;
  driver_fault_count_ = 0;
  failed_disables_ = 0;
  SupervisorDecision ignored;
  go(SupervisorState::kSafe, Trigger::kOperatorClear, now, ignored);
}

SupervisorDecision Supervisor::veto(Trigger why, hal::Timestamp now) {
  SupervisorDecision d;
  go(SupervisorState::kSafe, why, now, d);
  fill(d);
  return d;
}

void Supervisor::fill(SupervisorDecision& d) const {
  d.state = state_;
  d.in_control = state_ == SupervisorState::kRun || state_ == SupervisorState::kDegraded;
  d.enable = d.in_control || (config_.enable_in_safe && !bus_stalled_);
  d.toggle_heartbeat = d.in_control;
  d.latched = latched_;
}

SupervisorDecision Supervisor::step(const SupervisorInputs& raw, hal::Timestamp now) {
  if (!started_) started_ = now;
  // A link that is not up yet queues INIT's setpoint for when it comes; once past INIT a
  // setpoint without a link is a failed write.
  SupervisorInputs in = raw;
  if (in.link_down) in.setpoint_write_failed = state_ != SupervisorState::kInit;
  bus_stalled_ = in.bus_stalled;
  update_counters(in);
  const Trigger hard = hard_trigger(in);
  const Trigger soft = soft_trigger(in);
  good_ = (hard == Trigger::kNone && soft == Trigger::kNone) ? good_ + 1 : 0;

  SupervisorDecision d;
  switch (state_) {
    case SupervisorState::kInit:
      // Before the first proof of health a silent sensor or outer controller keeps INIT (same
      // outputs as SAFE); every other hard trigger is a fault already.
      if (hard != Trigger::kNone && hard != Trigger::kSensorStale && hard != Trigger::kDemandStale) {
        go(SupervisorState::kSafe, hard, now, d);
      } else if (in.link_down && now - *started_ >= link_timeout_) {
        go(SupervisorState::kSafe, Trigger::kLinkTimeout, now, d);
      } else if (good_ >= config_.recovery_periods && !in.link_down) {
        go(SupervisorState::kRun, Trigger::kGoodPeriods, now, d);
      }
      break;
    case SupervisorState::kRun:
      if (hard != Trigger::kNone) {
        go(SupervisorState::kSafe, hard, now, d);
      } else if (soft != Trigger::kNone) {
        go(SupervisorState::kDegraded, soft, now, d);
      }
      break;
    case SupervisorState::kDegraded:
      if (hard != Trigger::kNone) {
        go(SupervisorState::kSafe, hard, now, d);
      } else if (good_ >= config_.degraded_clear_periods) {
        go(SupervisorState::kRun, Trigger::kGoodPeriods, now, d);
      }
      break;
    case SupervisorState::kSafe:
      if (!latched_ && failed_disables_ >= config_.line_failure_periods) {
        // The driver cannot be switched off: only the 0 A setpoint holds it. No recovery
        // until an operator has looked.
        latched_ = true;
        go(SupervisorState::kSafe, Trigger::kDisableFailed, now, d);
      } else if (!shutdown_ && !latched_ && good_ >= config_.recovery_periods) {
        go(SupervisorState::kRun, Trigger::kGoodPeriods, now, d);
      }
      break;
    case SupervisorState::kCount: break;
  }
  fill(d);
  return d;
}

}  // namespace mrd::control
