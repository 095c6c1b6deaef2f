#pragma once

#include <optional>

#include "hal/sample.hpp"

namespace mrd::hal {

// One channel of samples for the loop: the LVDT, force mode's demand, its optional load cell.
// Whoever declares a channel says what its value means and its unit (firmware::HalDevices, the
// back ends' accessors). A back end provides one per channel it serves, as ros2_control's state
// interfaces or PX4's uORB subscriptions: one kind of handle, named by channel.
// Hot path: no throw, no allocation.
class SampleSource {
 public:
  virtual ~SampleSource() = default;
  // The newest sample that arrived since the previous call, or nullopt when none did. The
  // loop judges freshness from nullopt streaks, timestamps and sequence numbers
  // (control::SampleChecker, control::DemandChecker).
  [[nodiscard]] virtual std::optional<Sample> latest() = 0;
};

}  // namespace mrd::hal
