#pragma once

#include <random>

#include "model/damper_model.hpp"
#include "model/effects/sensor_delay.hpp"
#include "model/observer.hpp"

namespace mrd::sim {

struct PlantReading {
  double true_displacement = 0.0;  // [m]
  double lvdt_displacement = 0.0;  // what the sensor reports (late when sensor_delay is on) [m]
  double B = 0.0;                  // [T]
  double force = 0.0;              // true force [N]
  // What the rig measures besides the LVDT:
  double measured_force = 0.0;     // force + load-cell noise [N]
  double sensor_velocity = 0.0;    // the true velocity through the same delay as the LVDT [m/s]
  double coil_current = 0.0;       // the current that flows, after coil_lag [A]
  double temperature = 0.0;        // fluid temperature [degC] (ambient without thermal_drift)
};

struct PlantSettings {
  double sample_period = 1e-3;   // [s]
  double lvdt_noise_rms = 0.0;   // [m]
  double force_noise_rms = 0.0;  // load cell [N]
  unsigned seed = 1;
};

// The simulated damper: true J-A + Bingham physics driven by the true velocity, with the
// optional effects of `truth.effects` (each switched on and sized there), an LVDT with white
// noise and a load cell with white noise. The plant knows its velocity exactly; the controller
// does not. sensor_delay acts on the LVDT (a delay line), not inside the physics; every other
// effect acts inside the physics exactly as the observer models it (model::EffectChain).
// What drives the plant over one period: the rod's true motion and the commanded coil current,
// held over the period.
struct PlantInput {
  double displacement = 0.0;  // [m]
  double velocity = 0.0;      // [m/s]
  double coil_current = 0.0;  // [A]
};

// Allocation-free per step.
class DamperPlant {
 public:
  DamperPlant(const model::DamperModel& truth, const PlantSettings& settings)
      : physics_(physics_of(truth), model::ObserverSettings{settings.sample_period}),
        delayed_(truth.effects.get<model::SensorDelayEffect>().enabled),
        lvdt_delay_(truth.effects.get<model::SensorDelayEffect>(), settings.sample_period),
        velocity_delay_(truth.effects.get<model::SensorDelayEffect>(), settings.sample_period),
        rng_(settings.seed),
        noise_(0.0, settings.lvdt_noise_rms),
        force_rng_(settings.seed ^ 0x9e3779b97f4a7c15ULL),
        force_noise_(0.0, settings.force_noise_rms) {}
  // The firmware's simulated rig: 1 kHz, no load-cell noise.
  DamperPlant(const model::DamperModel& truth, double lvdt_noise_rms, unsigned seed);

  PlantReading step(const PlantInput& in);

  [[nodiscard]] const model::Observer& physics() const { return physics_; }
  // A fluid temperature [degC] imposed on the physics' temperature-dependent effects (a drift
  // scripted by a run rather than heated into the fluid); NaN returns to their own model.
  void set_fluid_temperature(double celsius) { physics_.set_measured_temperature(celsius); }

 private:
  // The physics without the sensor: the delay is the LVDT's, applied to its reading.
  static model::DamperModel physics_of(model::DamperModel truth) {
    truth.effects.get<model::SensorDelayEffect>().enabled = false;
    return truth;
  }

  model::Observer physics_;
  bool delayed_;
  model::SensorDelay lvdt_delay_;
  model::SensorDelay velocity_delay_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> noise_;
  std::mt19937_64 force_rng_;  // its own stream, so the LVDT noise does not depend on it
  std::normal_distribution<double> force_noise_;
};

}  // namespace mrd::sim
