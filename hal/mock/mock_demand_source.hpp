#pragma once

#include <cstdint>
#include <optional>

#include "hal/clock.hpp"
#include "hal/demand_source.hpp"
#include "hal/mock/fault_script.hpp"

namespace mrd::hal::mock {

// The outer controller's force demand as the test or the simulated rig sets it (set_demand),
// one new sample per call, with the script's demand faults on top: missing, stale (the same
// sample again), not finite, out of range.
class MockDemandSource final : public DemandSource {
 public:
  MockDemandSource(const Clock& clock, const FaultScript& script) : clock_(clock), script_(script) {}

  void set_demand(double newtons) { demand_ = newtons; }
  [[nodiscard]] std::optional<DemandSample> latest_demand() override;

 private:
  const Clock& clock_;
  const FaultScript& script_;
  double demand_ = 0.0;
  std::optional<DemandSample> last_;
  std::uint32_t sequence_ = 0;
};

}  // namespace mrd::hal::mock
