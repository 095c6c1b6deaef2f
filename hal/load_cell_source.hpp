#pragma once

#include <optional>

#include "hal/sample.hpp"

namespace mrd::hal {

// The damper force a load cell in series with the damper measures [N], with the sign of the
// demand's (docs/FORCE-CONTROL.md, "Load-cell feedback"). Optional: force mode runs on the
// model alone without one.
using LoadCellSample = Sample;

// Force mode's optional load-cell channel. Hot path: no throw, no allocation.
class LoadCellSource {
 public:
  virtual ~LoadCellSource() = default;
  // (Named apart from the other channels' calls: one bus back end provides several.)
  // The newest measurement that arrived since the previous call, or nullopt when none did.
  [[nodiscard]] virtual std::optional<LoadCellSample> latest_load_cell() = 0;
};

}  // namespace mrd::hal
