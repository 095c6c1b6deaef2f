#pragma once

#include <array>

#include "common/validation_report.hpp"

namespace mrd::model {

// The LVDT (its conditioner, filter and bus) reports the displacement `delay` late:
//   x_measured(t) = x(t - d).
// For a damper whose force flips with the sign of v this matters most at reversals, where the
// reading says the piston still moves one way while the force already pushes the other.
struct SensorDelayParams {
  bool enabled = false;
  double delay = 2e-3;  // d [s], at most kMaxSensorDelay
};

inline constexpr double kMaxSensorDelay = 0.1;  // [s]

ValidationReport validate(const SensorDelayParams& params);

// The sensor itself, for the simulated plant: a delay line of fixed capacity (no heap) with
// linear interpolation between samples for a delay that is not a whole number of periods.
// kCapacity covers kMaxSensorDelay at 20 kHz, the loop's highest rate; a longer delay (in
// periods) is cut to the capacity. Until the line has filled, the first value stands for the
// history before it (the rig was at rest there).
class SensorDelay {
 public:
  static constexpr int kCapacity = 2048;

  SensorDelay(const SensorDelayParams& params, double sample_period);

  // Takes the present value; returns the value `delay` ago.
  double step(double value);
  [[nodiscard]] double delay_in_periods() const { return whole_ + fraction_; }
  void reset() { primed_ = false; }

 private:
  [[nodiscard]] double at(int age) const;  // the value `age` periods ago, age < kCapacity

  std::array<double, kCapacity> ring_{};
  int head_ = 0;  // index of the newest value
  int whole_;
  double fraction_;
  bool primed_ = false;
};

// The observer's side. It cannot look ahead, so it predicts where the piston is now from the
// delayed reading and the tracked motion, assuming constant acceleration over the delay:
//   x(t) = x_m + d v_m + d^2 a_m / 2,   v(t) = v_m + d a_m.
struct PredictedMotion {
  double displacement;  // [m]
  double velocity;      // [m/s]
};

[[nodiscard]] inline PredictedMotion predict_motion(double displacement, double velocity,
                                                    double acceleration, double delay) {
  return {displacement + delay * (velocity + 0.5 * delay * acceleration), velocity + delay * acceleration};
}

}  // namespace mrd::model
