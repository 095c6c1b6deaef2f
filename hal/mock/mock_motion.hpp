#pragma once

#include <chrono>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>

#include "common/sine_motion.hpp"
#include "hal/clock.hpp"
#include "hal/mock/mock_hal.hpp"

namespace mrd::hal::mock {

// Moves the mock LVDT along x = A sin(2 pi f t) from the first advance(), with white noise:
// the rig motion of the paper's Table 4 test for a controller on the mock HAL. Kinematics only;
// the damper's physics, its buses and its faults are mrd-plant's (sim/). Allocation-free.
class MockMotion {
 public:
  // `demand_damping` [N s/m]: the mock demand asks for that coefficient times the motion's
  // velocity, a dissipative demand for force mode (a number, not physics: hal knows none).
  MockMotion(double amplitude, double frequency, double noise_rms, std::uint32_t seed, double demand_damping = 0.0)
      : sine_{.amplitude = amplitude, .frequency = frequency}, demand_damping_(demand_damping), rng_(seed),
        noise_(0.0, noise_rms) {}

  // Before each cycle: the mock clock to `now`, the LVDT to the motion at `now`, the demand to
  // c v at `now`.
  void advance(MockHal& hal, Timestamp now) {
    if (!start_) start_ = now;
    hal.clock.set(now);
    const double t = std::chrono::duration<double>(now - *start_).count();
    const double noise = noise_.stddev() > 0.0 ? noise_(rng_) : 0.0;
    hal.lvdt.set_value(sine_.displacement(t) + noise);
    // c A w cos(w t) multiplied in this order, as the mock always has: its runs stay bit for bit.
    const double w = sine_.angular_frequency();
    const double demand = demand_damping_ * sine_.amplitude * w * std::cos(w * t);
    hal.demand.set_value(demand);
    // The mock load cell reads the demand: a rig that delivers exactly what is asked (a number
    // for the wiring, as the demand is).
    hal.load_cell.set_value(demand);
  }

 private:
  SineMotion sine_;
  double demand_damping_;  // [N s/m]
  std::optional<Timestamp> start_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> noise_;
};

}  // namespace mrd::hal::mock
