#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <tuple>

#include "model/bingham_damper.hpp"
#include "model/current_range.hpp"
#include "model/effects/effect_set.hpp"

namespace mrd::model {

// The run-time state of the optional effects. The Observer calls the hooks in this order in a
// step; each effect's descriptor says which hooks it has (effect_traits.hpp), and effects that
// share a hook apply in AllEffects' order:
//   1. motion(reading, a): the motion now from the reading (sensor_delay's prediction);
//   2. coil_current(command): the current that flows, from the one commanded (coil_lag);
//   -- J-A (Eq. 1-10) and Eq. 13 on that current --
//   3. yield_factor(), viscosity_factor(): factors on tau_y and c0 (thermal_drift);
//   4. fluid_force(FluidForceParts): the fluid force in place of Eq. 11-12's (preyield);
//   5. force_factor(x): a factor on the fluid force (stroke_end_air);
//   6. added_force(x) or state_force(x, v, a, I, B): a force added to the fluid's (gas_spring,
//      learned_terms);
//   7. dissipate(F_fluid v): the fluid's heating (thermal_drift).
// A disabled effect's hooks are not called and its state is not touched. Every element exists
// whether enabled or not, so nothing is allocated and the layout does not depend on the config.
class EffectChain {
 public:
  EffectChain(const EffectSet& effects, double sample_period);

  [[nodiscard]] bool active() const { return active_; }
  [[nodiscard]] const EffectSet& config() const { return config_; }
  // Whether a hook needs the tracked acceleration (the observer then runs its tracker even when
  // the rig has a velocity sensor).
  [[nodiscard]] bool needs_acceleration() const { return needs_acceleration_; }

  // The length [s] of the steps from here on: the sample period unless the samples were taken
  // unevenly (an offline run at its recorded times). Each time-dependent element (a lag, a
  // cooling, an integration over dx = v dt, a derivative) takes it; repeating a length costs a
  // comparison.
  void set_step(double dt);
  [[nodiscard]] PredictedMotion motion(const PredictedMotion& reading, double acceleration) const;
  double coil_current(double command);
  // Hook 2 inverted, for a force or B command: the currents that can flow at the end of `dt`
  // for commands in `commands`, and the command that makes `flowing` flow then (clamped to
  // `commands`). Without an enabled effect that changes the current, what is commanded flows.
  // Exact for one such effect (today only coil_lag); several would invert in reverse order.
  [[nodiscard]] CurrentRange reachable_current(const CurrentRange& commands, double dt) const;
  [[nodiscard]] double command_for(double flowing, double dt, const CurrentRange& commands) const;
  [[nodiscard]] double yield_factor() const;
  // Steps 3-4: the fluid force [N] from the yield stress already scaled by yield_factor().
  double fluid_force(const BinghamDamper& damper, const FlowState& flow);
  double force_factor(double displacement);
  double added_force(const ForceState& state);
  void dissipate(double power);

  // The current that flowed in the last step [A], after the lag; the steps above only run,
  // and so this is only kept, while active().
  [[nodiscard]] double coil_current() const { return coil_current_; }
  // The fluid temperature [degC] an effect keeps (lumped or measured), or its ambient when it is
  // off; NaN when no effect keeps one.
  [[nodiscard]] double temperature() const;
  // A measured fluid temperature [degC] for the effects that use one (NaN: back to their model).
  void set_measured_temperature(double celsius);
  template <typename E>
  [[nodiscard]] const typename E::Element& element() const {
    return std::get<typename E::Element>(elements_);
  }
  void reset();

 private:
  template <typename List>
  struct Elements;
  template <typename... E>
  struct Elements<EffectList<E...>> {
    using type = std::tuple<typename E::Element...>;
  };

  // f.template operator()<E>(element) for every enabled effect, in order.
  template <typename F>
  void for_each_enabled(F&& f);
  template <typename F>
  void for_each_enabled(F&& f) const;

  EffectSet config_;
  bool active_;
  bool needs_acceleration_ = false;
  std::array<bool, AllEffects::size> enabled_{};
  double coil_current_ = 0.0;
  double step_;  // [s]
  Elements<AllEffects>::type elements_;
};

template <typename F>
void EffectChain::for_each_enabled(F&& f) {
  std::size_t i = 0;
  for_each_effect_type([&]<typename E>() {
    if (enabled_[i++]) f.template operator()<E>(std::get<typename E::Element>(elements_));
  });
}

template <typename F>
void EffectChain::for_each_enabled(F&& f) const {
  std::size_t i = 0;
  for_each_effect_type([&]<typename E>() {
    if (enabled_[i++]) f.template operator()<E>(std::get<typename E::Element>(elements_));
  });
}

}  // namespace mrd::model
