#pragma once

#include <optional>

#include "config/controller_config.hpp"
#include "hal/clock.hpp"
#include "hal/mock/mock_hal.hpp"
#include "hal/mock/mock_motion.hpp"

namespace mrd::firmware {

// Time for the mock HAL, when the config picks it: before each cycle (or probe reading) the
// mock's manual clock goes to `now` and, with the mock LVDT, the LVDT moves on the
// [simulation] sine. Nothing to do on the bus back ends, which run on the real clock.
class MockDrive {
 public:
  MockDrive(const config::ControllerConfig& config, hal::mock::MockHal* mock) : mock_(mock) {
    if (mock_ != nullptr && config.backends.lvdt == config::DeviceBackend::kMock) {
      const auto& s = config.simulation;
      motion_.emplace(s.amplitude, s.frequency, s.lvdt_noise, s.seed, s.demand_damping);
    }
  }

  void advance(hal::Timestamp now) {
    if (motion_) {
      motion_->advance(*mock_, now);
    } else if (mock_ != nullptr) {
      mock_->clock.set(now);
    }
  }
  [[nodiscard]] bool moves_lvdt() const { return motion_.has_value(); }

 private:
  hal::mock::MockHal* mock_;
  std::optional<hal::mock::MockMotion> motion_;
};

}  // namespace mrd::firmware
