#include "hal/mock/mock_current_driver.hpp"

namespace mrd::hal::mock {

IoStatus MockCurrentDriver::write_setpoint(double amps) {
  const Timestamp now = clock_.now();
  if (script_.is_active(FaultKind::kDriverWriteFails, now)) {
    ++failed_writes_;
    return IoStatus::kIoError;
  }
  // Queued, as an asynchronous back end would: the refusal arrives as an ack, not a status.
  if (script_.is_active(FaultKind::kSetpointRefused, now)) {
    ++acks_.refused;
    return IoStatus::kOk;
  }
  ++acks_.accepted;
  setpoint_ = amps;
  ++writes_;
  return IoStatus::kOk;
}

std::optional<CurrentReading> MockCurrentDriver::measured() {
  const Timestamp now = clock_.now();
  if (script_.is_active(FaultKind::kReadbackSilent, now)) return std::nullopt;
  const ScriptedFault* bias = script_.active(FaultKind::kCurrentBias, now);
  return CurrentReading{setpoint_ + (bias != nullptr ? bias->parameter : 0.0), now};
}

}  // namespace mrd::hal::mock
