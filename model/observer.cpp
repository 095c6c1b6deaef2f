#include "model/observer.hpp"

#include <algorithm>

namespace mrd::model {

Observer::Observer(const DamperModel& model, const ObserverSettings& settings)
    : sample_period_(settings.sample_period),
      magnetics_(model.jiles_atherton, model.circuit, model.integration),
      yield_stress_(model.fluid),
      damper_(model.geometry, model.fluid.viscosity, model.fluid.flow_index),
      velocity_filter_(settings.sample_period, settings.velocity_cutoff_frequency),
      effects_(model.effects, settings.sample_period) {}

ObserverEstimate Observer::step(const Measurement& m) {
  effects_.set_step(m.step_duration.value_or(sample_period_));
  const PredictedMotion motion = track(m);
  // One well-predicted branch: with every effect off this is the base model unchanged.
  if (!effects_.active()) [[likely]] return base_force(motion, magnetics_.apply_current(m.coil_current));
  const PredictedMotion now = effects_.motion(motion, velocity_filter_.acceleration());
  const double flowing = effects_.coil_current(m.coil_current);
  return force_with_effects(now, {.coil_current = flowing, .B = magnetics_.apply_current(flowing)});
}

ObserverEstimate Observer::step_at_induction(const Measurement& m, double B) {
  effects_.set_step(m.step_duration.value_or(sample_period_));
  const PredictedMotion motion = track(m);
  if (!effects_.active()) return base_force(motion, B);
  return force_with_effects(effects_.motion(motion, velocity_filter_.acceleration()),
                            {.coil_current = m.coil_current, .B = B});
}

PredictedMotion Observer::track(const Measurement& m) {
  const SampleTiming timing =
      m.timing.value_or(SampleTiming{.fresh = true, .interval = m.step_duration.value_or(sample_period_), .age = 0.0});
  // Without a velocity sensor the tracker gives the velocity; with one, it runs only for an
  // effect that needs the acceleration.
  if ((!m.velocity || effects_.needs_acceleration()) && timing.fresh) {
    velocity_filter_.update(m.displacement, timing.interval);
  }
  if (m.velocity) return {.displacement = m.displacement, .velocity = *m.velocity};
  // Carried to this step by the sample's age, at most two periods, so that a silent sensor
  // cannot extrapolate far.
  return {.displacement = m.displacement,
          .velocity = velocity_filter_.velocity_after(std::clamp(timing.age, 0.0, 2.0 * sample_period_))};
}

ObserverEstimate Observer::base_force(const PredictedMotion& now, double B) {
  estimate_.B = B;
  estimate_.yield_stress = yield_stress_(B) * yield_scale_;
  estimate_.velocity = now.velocity;
  estimate_.force = damper_.force({.velocity = now.velocity, .yield_stress = estimate_.yield_stress});
  return estimate_;
}

ObserverEstimate Observer::force_with_effects(const PredictedMotion& now, const Field& field) {
  estimate_.B = field.B;
  estimate_.yield_stress = yield_stress_(estimate_.B) * effects_.yield_factor() * yield_scale_;
  estimate_.velocity = now.velocity;
  const double fluid =
      effects_.fluid_force(damper_, {.velocity = now.velocity, .yield_stress = estimate_.yield_stress}) *
      effects_.force_factor(now.displacement);
  estimate_.force = fluid + effects_.added_force({.displacement = now.displacement,
                                                  .velocity = now.velocity,
                                                  .coil_current = field.coil_current,
                                                  .B = field.B});
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
