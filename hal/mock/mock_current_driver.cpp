#include "hal/mock/mock_current_driver.hpp"

namespace mrd::hal::mock {

IoStatus MockCurrentDriver::write_setpoint(double amps) {
  if (script_.is_active(FaultKind::kDriverWriteFails, clock_.now())) {
    ++failed_writes_;
    return IoStatus::kIoError;
  }
  setpoint_ = amps;
  ++writes_;
  return IoStatus::kOk;
}

std::optional<CurrentReading> MockCurrentDriver::measured() {
  const Timestamp now = clock_.now();
  const ScriptedFault* bias = script_.active(FaultKind::kCurrentBias, now);
  return CurrentReading{setpoint_ + (bias != nullptr ? bias->parameter : 0.0), now};
}

}  // namespace mrd::hal::mock
