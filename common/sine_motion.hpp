#pragma once

#include <cmath>
#include <numbers>

namespace mrd {

// The paper's rig motion, x = A sin(2 pi f t) in metres (Table 4's tests), and its exact
// velocity. The one sine of the project: the mock HAL's LVDT (hal/mock/mock_motion.hpp) and the
// simulated rig's profiles (sim/displacement_profile.hpp) both move along it.
struct SineMotion {
  double amplitude = 0.040;  // [m]
  double frequency = 0.5;    // [Hz]

  [[nodiscard]] double displacement(double t) const { return amplitude * std::sin(angular_frequency() * t); }
  [[nodiscard]] double velocity(double t) const {
    const double w = angular_frequency();
    return amplitude * w * std::cos(w * t);
  }
  [[nodiscard]] double angular_frequency() const { return 2.0 * std::numbers::pi * frequency; }  // [rad/s]
};

}  // namespace mrd
