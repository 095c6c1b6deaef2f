#pragma once

#include "model/bingham_damper.hpp"
#include "model/effects/effect_set.hpp"

namespace mrd::model {

// The run-time state of the optional effects, in the order the Observer applies them in a step:
//   1. sensor_delay: predict the motion now from the delayed reading (predict_motion);
//   2. coil_lag: the current that flows, from the one commanded;
//   -- J-A (Eq. 1-10) and Eq. 13 on that current --
//   3. thermal_drift: scale tau_y and c0 by the temperature factors;
//   4. preyield_hysteresis: the fluid force with Bouc-Wen's z (else Eq. 11-12);
//   5. stroke_end_air: scale the fluid force after a reversal near a stroke end;
//   6. gas_spring: add F0 + k x;
//   7. thermal_drift: heat the fluid with the dissipated power F_fluid v.
// A disabled stage is the identity and does not touch its state. Every instance exists whether
// enabled or not, so nothing is allocated and the layout does not depend on the config.
class EffectChain {
 public:
  EffectChain(const EffectSet& effects, double sample_period);

  [[nodiscard]] bool active() const { return active_; }
  [[nodiscard]] const EffectSet& config() const { return config_; }

  [[nodiscard]] PredictedMotion motion(double displacement, double velocity, double acceleration) const;
  double coil_current(double command);
  [[nodiscard]] double yield_factor() const;
  // Steps 3-4: the fluid force [N] from the yield stress already scaled by yield_factor().
  double fluid_force(const BinghamDamper& damper, double yield_stress, double velocity);
  double stroke_factor(double displacement);
  [[nodiscard]] double gas_force(double displacement) const;
  void dissipate(double power);

  // The current that flowed in the last step [A], after the lag; the steps above only run,
  // and so this is only kept, while active().
  [[nodiscard]] double coil_current() const { return coil_current_; }
  // The fluid temperature [degC]: the lumped or measured one, or the ambient when the effect
  // is off.
  [[nodiscard]] double temperature() const;
  void set_measured_temperature(double celsius) { thermal_.set_measured_temperature(celsius); }
  [[nodiscard]] const PreyieldHysteresis& preyield() const { return preyield_; }
  [[nodiscard]] const StrokeEndAir& stroke_end_air() const { return stroke_end_; }
  void reset();

 private:
  EffectSet config_;
  bool active_;
  double coil_current_ = 0.0;
  CoilLag coil_lag_;
  PreyieldHysteresis preyield_;
  GasSpring gas_;
  ThermalDrift thermal_;
  StrokeEndAir stroke_end_;
};

}  // namespace mrd::model
