#include "hal/mock/fault_script.hpp"

#include <cmath>
#include <string>

namespace mrd::hal::mock {

std::string_view to_string(FaultKind k) {
  switch (k) {
    case FaultKind::kSensorTimeout: return "sensor_timeout";
    case FaultKind::kStaleValue: return "stale_value";
    case FaultKind::kFrozenValue: return "frozen_value";
    case FaultKind::kNotANumber: return "nan";
    case FaultKind::kOutOfRange: return "out_of_range";
    case FaultKind::kCorruptedFrame: return "corrupted_frame";
    case FaultKind::kDroppedSample: return "dropped_sample";
    case FaultKind::kDriverFault: return "driver_fault";
    case FaultKind::kFaultLineUnreadable: return "fault_line_unreadable";
    case FaultKind::kCurrentBias: return "current_bias";
    case FaultKind::kDriverWriteFails: return "driver_write_fails";
    case FaultKind::kReadbackSilent: return "readback_silent";
    case FaultKind::kSetpointRefused: return "setpoint_refused";
    case FaultKind::kEnableWriteFails: return "enable_write_fails";
    case FaultKind::kHeartbeatWriteFails: return "heartbeat_write_fails";
    case FaultKind::kDisplacementJump: return "displacement_jump";
    case FaultKind::kFutureTimestamp: return "future_timestamp";
    case FaultKind::kDemandMissing: return "demand_missing";
    case FaultKind::kDemandStale: return "demand_stale";
    case FaultKind::kDemandNotFinite: return "demand_not_finite";
    case FaultKind::kDemandOutOfRange: return "demand_out_of_range";
    case FaultKind::kOldTimestamp: return "old_timestamp";
    case FaultKind::kCount: break;
  }
  return "unknown";
}

const ScriptedFault* FaultScript::active(FaultKind kind, Timestamp now) const {
  for (const auto& f : faults_) {
    if (f.kind == kind && now >= f.start && now < f.end) return &f;
  }
  return nullptr;
}

ValidationReport FaultScript::validate() const {
  ValidationReport r;
  for (std::size_t i = 0; i < faults_.size(); ++i) {
    const auto& f = faults_[i];
    const std::string at = "faults[" + std::to_string(i) + "]";
    r.check(f.kind < FaultKind::kCount, at + ".kind", "unknown fault kind");
    r.check(f.end > f.start, at + ".end", "must be after start");
    r.check(std::isfinite(f.parameter), at + ".parameter", "must be finite");
    if (f.kind == FaultKind::kDroppedSample) {
      r.check(f.parameter >= 1.0, at + ".parameter", "drop period must be >= 1 sample");
    }
  }
  return r;
}

}  // namespace mrd::hal::mock
