#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <array>

#include "common/validation_report.hpp"
#include "model/effects/effect_traits.hpp"

namespace mrd::model {

// The LVDT (its conditioner, filter and bus) reports the displacement `delay` late:
//   x_measured(t) = x(t - d).
// For a damper whose force flips with the sign of v this matters most at reversals, where the
// reading says the piston still moves one way while the force already pushes the other.
struct SensorDelayParams {
  bool enabled = false;
  double delay = 2e-3;  // d [s], at most kMaxSensorDelay

  bool operator==(const SensorDelayParams&) const = default;
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

// How far ahead to predict, and the acceleration to predict with.
struct Lookahead {
  double delay;         // [s]
  double acceleration;  // [m/s^2]
};

[[nodiscard]] inline PredictedMotion predict_motion(const PredictedMotion& reading, const Lookahead& ahead) {
  const double d = ahead.delay;
  return {.displacement = reading.displacement + d * (reading.velocity + 0.5 * d * ahead.acceleration),
          .velocity = reading.velocity + d * ahead.acceleration};
}

// The observer's side of the effect: the prediction above with the configured delay.
class SensorDelayPrediction {
 public:
  SensorDelayPrediction(const SensorDelayParams& params, double /*sample_period*/) : delay_(params.delay) {}
  [[nodiscard]] PredictedMotion predict(const PredictedMotion& reading, double acceleration) const {
    return predict_motion(reading, {.delay = delay_, .acceleration = acceleration});
  }

 private:
  double delay_;
};

// The descriptor (effect_traits.hpp): a delay from a tenth of a sample to 5 % of the run.
struct SensorDelayEffect : EffectTraitsBase<SensorDelayParams> {
  using Element = SensorDelayPrediction;
  static constexpr std::string_view kName = "sensor_delay";
  static constexpr std::string_view kSeparatedBy =
      "a faster motion at constant current (a delay grows with the frequency; most effects do not)";
  // Hook (effect_chain.hpp): the motion now from the delayed reading; needs the tracked
  // acceleration, so the observer runs its velocity tracker even with a velocity sensor.
  static constexpr bool kNeedsAcceleration = true;
  static PredictedMotion motion(const Element& e, const PredictedMotion& reading, double acceleration) {
    return e.predict(reading, acceleration);
  }

  template <typename Visitor>
  static void fields(Params& p, Visitor&& v) {
    v("enabled", p.enabled);
    v("delay", p.delay);
  }

  // Logarithmic, so that a delay below one sample is as easy to find as one of 50 ms.
  static constexpr std::array kSearch = {SearchCoordinate{
      "log10 delay [s]", [](const RunScales& s) { return std::log10(0.1 * s.sample_period); },
      [](const RunScales& s) {
        const double longest = std::min(kMaxSensorDelay, 0.05 * s.duration);
        return std::log10(std::max(longest, 2.0 * s.sample_period));
      }}};
  static void apply(Params& p, std::span<const double> x, const RunScales&) {
    p = {true, std::min(std::pow(10.0, x[0]), kMaxSensorDelay)};
  }
  static void coordinates(const Params& p, const RunScales&, std::span<double> x) { x[0] = std::log10(p.delay); }
  static std::optional<std::string> implausible(const Params& p, const RunScales& s);
  template <typename Visitor>
  static void report(const Params& p, Visitor&& v) {
    v("delay_s", p.delay);
  }
  static Params nominal(DamperClassId damper) {
    // The 1 kN class moves at up to 5 Hz: a few ms is already a large phase error there.
    return {.enabled = false, .delay = damper == DamperClassId::k50kN ? 5e-3 : 1.5e-3};
  }
  static void resize(Params& p, double size, double /*dissipated_energy*/) {
    p = {true, std::min(size * p.delay, kMaxSensorDelay)};
  }
  static std::string size_summary(const Params& p);
};
}  // namespace mrd::model
