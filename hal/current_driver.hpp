#pragma once

#include <optional>

#include "hal/clock.hpp"
#include "hal/status.hpp"

namespace mrd::hal {

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
};

}  // namespace mrd::hal
