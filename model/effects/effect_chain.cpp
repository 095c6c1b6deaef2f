#include "model/effects/effect_chain.hpp"

namespace mrd::model {

EffectChain::EffectChain(const EffectSet& effects, double sample_period)
    : config_(effects),
      active_(effects.any_enabled()),
      coil_lag_(effects.coil_lag, sample_period),
      preyield_(effects.preyield_hysteresis, sample_period),
      gas_(effects.gas_spring),
      thermal_(effects.thermal_drift, sample_period),
      stroke_end_(effects.stroke_end_air) {}

PredictedMotion EffectChain::motion(double displacement, double velocity, double acceleration) const {
  if (!config_.sensor_delay.enabled) return {displacement, velocity};
  return predict_motion(displacement, velocity, acceleration, config_.sensor_delay.delay);
}

double EffectChain::coil_current(double command) {
  coil_current_ = config_.coil_lag.enabled ? coil_lag_.step(command) : command;
  return coil_current_;
}

double EffectChain::yield_factor() const {
  return config_.thermal_drift.enabled ? thermal_.yield_factor() : 1.0;
}

double EffectChain::fluid_force(const BinghamDamper& damper, double yield_stress, double velocity) {
  const double viscous_coefficient = config_.thermal_drift.enabled
                                         ? damper.viscous_coefficient() * thermal_.viscosity_factor()
                                         : damper.viscous_coefficient();
  const double yield_force = damper.yield_force(yield_stress);
  const double sign_term = damper.sign_term(velocity);
  if (!config_.preyield_hysteresis.enabled) return yield_force * sign_term + viscous_coefficient * velocity;
  preyield_.step(velocity);
  return preyield_.fluid_force(yield_force, sign_term, viscous_coefficient * velocity);
}

double EffectChain::stroke_factor(double displacement) {
  return config_.stroke_end_air.enabled ? stroke_end_.step(displacement) : 1.0;
}

double EffectChain::gas_force(double displacement) const {
  return config_.gas_spring.enabled ? gas_.force(displacement) : 0.0;
}

void EffectChain::dissipate(double power) {
  if (config_.thermal_drift.enabled) thermal_.heat(power);
}

double EffectChain::temperature() const {
  return config_.thermal_drift.enabled ? thermal_.temperature() : config_.thermal_drift.ambient_temperature;
}

void EffectChain::reset() {
  coil_current_ = 0.0;
  coil_lag_.reset();
  preyield_.reset();
  thermal_.reset();
  stroke_end_.reset();
}

}  // namespace mrd::model
