#include "hal/mock/mock_digital_lines.hpp"

namespace mrd::hal::mock {

IoStatus MockDigitalLines::set_enable(bool enabled) {
  if (script_.is_active(FaultKind::kEnableWriteFails, clock_.now())) return IoStatus::kIoError;
  if (enabled != enabled_) ++enable_transitions_;
  enabled_ = enabled;
  return IoStatus::kOk;
}

std::optional<bool> MockDigitalLines::driver_fault() {
  const Timestamp now = clock_.now();
  if (script_.is_active(FaultKind::kFaultLineUnreadable, now)) return std::nullopt;
  return script_.is_active(FaultKind::kDriverFault, now);
}

IoStatus MockDigitalLines::write_heartbeat(bool high) {
  if (script_.is_active(FaultKind::kHeartbeatWriteFails, clock_.now())) return IoStatus::kIoError;
  if (high != heartbeat_level_) ++heartbeat_toggles_;
  heartbeat_level_ = high;
  return IoStatus::kOk;
}

}  // namespace mrd::hal::mock
