#pragma once

#include <cstdint>
#include <optional>

#include "hal/clock.hpp"
#include "hal/status.hpp"

namespace mrd::hal {

// Setpoints a back end that writes asynchronously has seen the device answer, counted since it
// started. Both zero: the back end does not report them (write_setpoint's status is all there is).
struct SetpointAcks {
  std::uint64_t accepted = 0;
  std::uint64_t refused = 0;  // the device answered the write with a refusal (a Modbus exception)
};

// A back end whose bus thread takes the setpoints write_setpoint queues: how many it took since
// start, and the longest a live, linked thread may go without taking one.
struct SetpointHandover {
  std::uint64_t taken = 0;
  Timestamp within{};
};

struct CurrentReading {
  double value = 0.0;     // A, as the driver measured it
  Timestamp timestamp{};  // when the back end received it
};

// The coil current driver. Hot path: no throw, no allocation.
class CurrentDriver {
 public:
  virtual ~CurrentDriver() = default;
  // Queues or sends the setpoint; the status says whether it could be.
  virtual IoStatus write_setpoint(double amps) = 0;
  // The newest measured current, or nullopt when the driver reports none (or none yet).
  [[nodiscard]] virtual std::optional<CurrentReading> measured() = 0;
  // What the device answered to the setpoints written after write_setpoint queued them.
  [[nodiscard]] virtual SetpointAcks setpoint_acks() const { return {}; }
  // nullopt: write_setpoint delivers the setpoint itself, on the caller's thread.
  [[nodiscard]] virtual std::optional<SetpointHandover> handover() const { return std::nullopt; }
};

}  // namespace mrd::hal
