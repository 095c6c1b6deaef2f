#include "model/effects/effect_chain.hpp"

#include <algorithm>
#include <limits>
#include <type_traits>

namespace mrd::model {

namespace {

template <typename E>
typename E::Element make_element(const EffectSet& effects, double sample_period) {
  if constexpr (std::is_constructible_v<typename E::Element, const typename E::Params&, double>) {
    return typename E::Element(effects.get<E>(), sample_period);
  } else {
    return typename E::Element(effects.get<E>());
  }
}

template <typename... E>
std::tuple<typename E::Element...> make_elements(EffectList<E...>, const EffectSet& effects, double sample_period) {
  return {make_element<E>(effects, sample_period)...};
}

}  // namespace

EffectChain::EffectChain(const EffectSet& effects, double sample_period)
    : config_(effects),
      active_(effects.any_enabled()),
      step_(sample_period),
      elements_(make_elements(AllEffects{}, effects, sample_period)) {
  std::size_t i = 0;
  effects.for_each([&]<typename E>(const typename E::Params& p) {
    enabled_[i++] = p.enabled;
    if constexpr (requires { E::kNeedsAcceleration; }) needs_acceleration_ = needs_acceleration_ || p.enabled;
  });
}

void EffectChain::set_step(double dt) {
  if (dt == step_ || !(dt > 0.0)) return;
  step_ = dt;
  for_each_enabled([&]<typename E>(typename E::Element& e) {
    if constexpr (requires { e.set_step(dt); }) e.set_step(dt);
  });
}

PredictedMotion EffectChain::motion(const PredictedMotion& reading, double acceleration) const {
  PredictedMotion now = reading;
  for_each_enabled([&]<typename E>(const typename E::Element& e) {
    if constexpr (requires { E::motion(e, now, acceleration); }) now = E::motion(e, now, acceleration);
  });
  return now;
}

double EffectChain::coil_current(double command) {
  double current = command;
  for_each_enabled([&]<typename E>(typename E::Element& e) {
    if constexpr (requires { E::coil_current(e, current); }) current = E::coil_current(e, current);
  });
  coil_current_ = current;
  return current;
}

CurrentRange EffectChain::reachable_current(const CurrentRange& commands, double dt) const {
  CurrentRange flowing = commands;
  for_each_enabled([&]<typename E>(const typename E::Element& e) {
    if constexpr (requires { E::reachable_current(e, dt, flowing); }) flowing = E::reachable_current(e, dt, flowing);
  });
  return flowing;
}

double EffectChain::command_for(double flowing, double dt, const CurrentRange& commands) const {
  double command = std::clamp(flowing, commands.lowest, commands.highest);
  for_each_enabled([&]<typename E>(const typename E::Element& e) {
    if constexpr (requires { E::command_for(e, flowing, dt, commands); }) command = E::command_for(e, flowing, dt, commands);
  });
  return command;
}

double EffectChain::yield_factor() const {
  double factor = 1.0;
  for_each_enabled([&]<typename E>(const typename E::Element& e) {
    if constexpr (requires { E::yield_factor(e); }) factor *= E::yield_factor(e);
  });
  return factor;
}

double EffectChain::fluid_force(const BinghamDamper& damper, const FlowState& flow) {
  double viscosity_factor = 1.0;
  for_each_enabled([&]<typename E>(const typename E::Element& e) {
    if constexpr (requires { E::viscosity_factor(e); }) viscosity_factor *= E::viscosity_factor(e);
  });
  // The seal's friction slides with the fluid's yield: the effects shape both alike.
  const FluidForceParts parts{.yield_force = damper.sliding_force(flow.yield_stress),
                              .sign_term = damper.sign_term(flow.velocity),
                              .viscous_force = damper.viscous_force(flow.velocity) * viscosity_factor,
                              .velocity = flow.velocity};
  double fluid = parts.yield_force * parts.sign_term + parts.viscous_force;
  for_each_enabled([&]<typename E>(typename E::Element& e) {
    if constexpr (requires { E::fluid_force(e, parts); }) fluid = E::fluid_force(e, parts);
  });
  return fluid;
}

double EffectChain::force_factor(double displacement) {
  double factor = 1.0;
  for_each_enabled([&]<typename E>(typename E::Element& e) {
    if constexpr (requires { E::force_factor(e, displacement); }) factor *= E::force_factor(e, displacement);
  });
  return factor;
}

double EffectChain::added_force(const ForceState& state) {
  double force = 0.0;
  for_each_enabled([&]<typename E>(typename E::Element& e) {
    if constexpr (requires { E::added_force(e, state.displacement); }) force += E::added_force(e, state.displacement);
    if constexpr (requires { E::state_force(e, state); }) force += E::state_force(e, state);
  });
  return force;
}

void EffectChain::dissipate(double power) {
  for_each_enabled([&]<typename E>(typename E::Element& e) {
    if constexpr (requires { E::dissipate(e, power); }) E::dissipate(e, power);
  });
}

double EffectChain::temperature() const {
  double celsius = std::numeric_limits<double>::quiet_NaN();
  config_.for_each([&]<typename E>(const typename E::Params& p) {
    const auto& e = std::get<typename E::Element>(elements_);
    if constexpr (requires { E::temperature(e, p, p.enabled); }) celsius = E::temperature(e, p, p.enabled);
  });
  return celsius;
}

void EffectChain::set_measured_temperature(double celsius) {
  for_each_effect_type([&]<typename E>() {
    auto& e = std::get<typename E::Element>(elements_);
    if constexpr (requires { E::set_measured_temperature(e, celsius); }) E::set_measured_temperature(e, celsius);
  });
}

void EffectChain::reset() {
  coil_current_ = 0.0;
  for_each_effect_type([&]<typename E>() {
    auto& e = std::get<typename E::Element>(elements_);
    if constexpr (requires { e.reset(); }) e.reset();
  });
}

}  // namespace mrd::model
