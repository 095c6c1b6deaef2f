#pragma once

#include <optional>

#include "firmware/controller_config.hpp"
#include "hal/clock.hpp"
#include "hal/mock/mock_hal.hpp"
#include "model/damper_model.hpp"
#include "sim/damper_plant.hpp"
#include "sim/displacement_profile.hpp"

namespace mrd::firmware {

// The "simulated rig" mode of mrd-controller: before each cycle it moves the mock HAL's clock
// to the cycle's release time, drives the simulated damper (sim::DamperPlant, true J-A and
// Bingham physics) with the current the mock driver holds, and hands the plant's LVDT reading
// to the mock LVDT. In process, allocation-free per cycle.
class SimulatedRig {
 public:
  // `truth` with its optional effects; `sample_period` is the loop's [s].
  SimulatedRig(const SimulationConfig& config, const model::DamperModel& truth, double sample_period,
               hal::mock::MockHal& hal);

  void advance(hal::Timestamp now);

  [[nodiscard]] const sim::PlantReading& last() const { return last_; }

 private:
  sim::SineProfile profile_;
  sim::DamperPlant plant_;
  hal::mock::MockHal& hal_;
  std::optional<hal::Timestamp> start_;
  sim::PlantReading last_;
};

}  // namespace mrd::firmware
