#pragma once

#include <optional>

#include "hal/status.hpp"

namespace mrd::hal {

// Driver enable out, driver fault in, heartbeat (watchdog) out. Logical levels: true means
// "enabled", "fault present", "heartbeat high", whatever the wiring's polarity.
// Hot path: no throw, no allocation.
class DigitalLines {
 public:
  virtual ~DigitalLines() = default;
  virtual IoStatus set_enable(bool enabled) = 0;
  // nullopt when the line cannot be read: the caller must treat that as a fault.
  [[nodiscard]] virtual std::optional<bool> driver_fault() = 0;

  IoStatus set_heartbeat(bool high) {
    heartbeat_ = high;
    return write_heartbeat(high);
  }
  IoStatus toggle_heartbeat() { return set_heartbeat(!heartbeat_); }
  [[nodiscard]] bool heartbeat() const { return heartbeat_; }

 protected:
  virtual IoStatus write_heartbeat(bool high) = 0;

 private:
  bool heartbeat_ = false;
};

}  // namespace mrd::hal
