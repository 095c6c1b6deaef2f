#pragma once

#include <cstdint>
#include <optional>

#include "hal/clock.hpp"
#include "hal/sample.hpp"

namespace mrd::hal {

using DisplacementSample = Sample;  // value [m]

// The LVDT. Hot path: no throw, no allocation.
class DisplacementSource {
 public:
  virtual ~DisplacementSource() = default;
  // The newest sample that arrived since the previous call, or nullopt when none did. The
  // loop judges freshness from nullopt streaks, timestamps and sequence numbers.
  [[nodiscard]] virtual std::optional<DisplacementSample> latest() = 0;
};

}  // namespace mrd::hal
