#include "model/observer.hpp"

#include <algorithm>

namespace mrd::model {

Observer::Observer(const DamperModel& model, const ObserverSettings& settings)
    : sample_period_(settings.sample_period),
      magnetics_(model.jiles_atherton, model.circuit, model.integration),
      yield_stress_(model.fluid),
      damper_(model.geometry, model.fluid.viscosity),
      velocity_filter_(settings.sample_period, settings.velocity_cutoff_frequency),
      effects_(model.effects, settings.sample_period) {}

ObserverEstimate Observer::step(double displacement, double coil_current) {
  return step(displacement, SampleTiming{true, sample_period_, 0.0}, coil_current);
}

ObserverEstimate Observer::step(double displacement, const SampleTiming& timing, double coil_current) {
  if (timing.fresh) velocity_filter_.update(displacement, timing.interval);
  const double velocity = velocity_filter_.velocity_after(std::clamp(timing.age, 0.0, 2.0 * sample_period_));
  if (effects_.active()) [[unlikely]] {
    return step_with_effects(displacement, velocity, coil_current, true);
  }
  return step(displacement, velocity, coil_current);
}

ObserverEstimate Observer::step(double displacement, double velocity, double coil_current) {
  // One well-predicted branch: with every effect off this is the base model unchanged.
  if (effects_.active()) [[unlikely]] {
    return step_with_effects(displacement, velocity, coil_current, false);
  }
  return base_force(velocity, magnetics_.apply_current(coil_current));
}

ObserverEstimate Observer::step_at_induction(double displacement, double velocity, double B) {
  if (effects_.active()) return force_with_effects(motion_now(displacement, velocity, false), B);
  return base_force(velocity, B);
}

ObserverEstimate Observer::base_force(double velocity, double B) {
  estimate_.B = B;
  estimate_.yield_stress = yield_stress_(B);
  estimate_.velocity = velocity;
  estimate_.force = damper_.force(velocity, estimate_.yield_stress);
  return estimate_;
}

ObserverEstimate Observer::step_with_effects(double displacement, double velocity,
                                             double coil_current, bool filtered) {
  const PredictedMotion now = motion_now(displacement, velocity, filtered);
  return force_with_effects(now, magnetics_.apply_current(effects_.coil_current(coil_current)));
}

PredictedMotion Observer::motion_now(double displacement, double velocity, bool filtered) {
  double acceleration = 0.0;
  if (effects_.config().sensor_delay.enabled) {
    // The prediction needs the acceleration, which only the tracker on the displacement has.
    if (!filtered) velocity_filter_.update(displacement);
    acceleration = velocity_filter_.acceleration();
  }
  return effects_.motion(displacement, velocity, acceleration);
}

ObserverEstimate Observer::force_with_effects(const PredictedMotion& now, double B) {
  estimate_.B = B;
  estimate_.yield_stress = yield_stress_(estimate_.B) * effects_.yield_factor();
  estimate_.velocity = now.velocity;
  const double fluid = effects_.fluid_force(damper_, estimate_.yield_stress, now.velocity) *
                       effects_.stroke_factor(now.displacement);
  estimate_.force = fluid + effects_.gas_force(now.displacement);
  effects_.dissipate(fluid * now.velocity);
  return estimate_;
}

void Observer::reset() {
  magnetics_.demagnetise();
  velocity_filter_.reset();
  effects_.reset();
  estimate_ = {};
}

}  // namespace mrd::model
