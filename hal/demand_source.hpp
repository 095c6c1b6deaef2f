#pragma once

#include <optional>

#include "hal/sample.hpp"

namespace mrd::hal {

// A force the outer controller (skyhook, clipped-optimal, LQG) demands of the damper [N], with
// the sign of the motion it resists (docs/FORCE-CONTROL.md).
using DemandSample = Sample;

// The force-mode demand channel. Hot path: no throw, no allocation.
class DemandSource {
 public:
  virtual ~DemandSource() = default;
  // (Named apart from DisplacementSource::latest: one bus back end provides both.)
  // The newest demand that arrived since the previous call, or nullopt when none did; judged
  // by control::DemandChecker as the LVDT's samples are by SampleChecker.
  [[nodiscard]] virtual std::optional<DemandSample> latest_demand() = 0;
};

}  // namespace mrd::hal
