#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "common/validation_report.hpp"
#include "model/effects/coil_lag.hpp"
#include "model/effects/effect_traits.hpp"
#include "model/effects/gas_spring.hpp"
#include "model/effects/learned_terms.hpp"
#include "model/effects/preyield_hysteresis.hpp"
#include "model/effects/sensor_delay.hpp"
#include "model/effects/stroke_end_air.hpp"
#include "model/effects/thermal_drift.hpp"

namespace mrd::model {

template <typename... E>
struct EffectList {
  static constexpr std::size_t size = sizeof...(E);
};

// The optional effects the base J-A + Bingham model lacks (docs/MODEL.md, "Optional effects"),
// in the order the observer applies them (EffectChain). This is the one list of them: every
// loop over effects, in the config, the observer, the tools and the reports, walks it.
using AllEffects = EffectList<SensorDelayEffect, CoilLagEffect, ThermalDriftEffect, PreyieldHysteresisEffect,
                              StrokeEndAirEffect, GasSpringEffect, LearnedTermsEffect>;

// Calls f.template operator()<E>() for every effect E of the list, in order.
template <typename F, typename... E>
constexpr void for_each_effect_type(EffectList<E...>, F&& f) {
  (f.template operator()<E>(), ...);
}
template <typename F>
constexpr void for_each_effect_type(F&& f) {
  for_each_effect_type(AllEffects{}, std::forward<F>(f));
}

// The effects' names, as the config tables ([damper.effects.<name>]), the tools and the
// reports spell them, in the list's order.
inline constexpr auto kEffectNames = [] {
  std::array<std::string_view, AllEffects::size> names{};
  std::size_t i = 0;
  for_each_effect_type([&]<typename E>() { names[i++] = E::kName; });
  return names;
}();

namespace detail {
template <typename List>
struct ParamsTuple;
template <typename... E>
struct ParamsTuple<EffectList<E...>> {
  using type = std::tuple<typename E::Params...>;
};
}  // namespace detail

// Every effect's parameters, each switched on and sized on its own. All are off by default, and
// then the observer runs exactly the base model.
class EffectSet {
 public:
  template <typename E>
  [[nodiscard]] typename E::Params& get() { return std::get<typename E::Params>(params_); }
  template <typename E>
  [[nodiscard]] const typename E::Params& get() const { return std::get<typename E::Params>(params_); }

  // f.template operator()<E>(params) for every effect, in the list's order.
  template <typename F>
  void for_each(F&& f) {
    for_each_effect_type([&]<typename E>() { f.template operator()<E>(get<E>()); });
  }
  template <typename F>
  void for_each(F&& f) const {
    for_each_effect_type([&]<typename E>() { f.template operator()<E>(get<E>()); });
  }

  [[nodiscard]] bool any_enabled() const;
  bool operator==(const EffectSet&) const = default;

 private:
  detail::ParamsTuple<AllEffects>::type params_;
};

// Every effect's parameters, enabled or not (a disabled table with a bad value is still a bad
// file), with field paths such as "coil_lag.time_constant".
ValidationReport validate(const EffectSet& effects);

// One effect's descriptor (effect_traits.hpp) as a run-time record, for the tools that pick
// effects by name: the residual search, the simulator and the reports.
struct EffectInfo {
  std::string_view name;
  std::string_view separated_by;  // the test run that tells it from its look-alikes
  std::span<const std::string_view> term_forms;  // library terms that are its own physics
  bool changes_induction = false;
  bool sized_by_dissipated_energy = false;
  bool named_candidate = true;  // searched by mrd-residual and sized by the simulator
  std::span<const SearchCoordinate> search;
  std::span<const LinearColumn> linear;
  std::span<const bool> linear_non_negative;  // per linear column; empty: no sign constraint
  bool (*enabled)(const EffectSet&);
  void (*disable)(EffectSet&);
  // The search coordinates x of the effect set into `effects` (the effect on), and back.
  void (*apply)(EffectSet& effects, std::span<const double> x, const RunScales& scales);
  void (*coordinates)(const EffectSet& effects, const RunScales& scales, std::span<double> x);
  // Adds the coefficients of the linear columns fitted on top (the effect on).
  void (*add_linear)(EffectSet& effects, std::span<const double> coefficients);
  // The present values of the parameters the linear columns add to (0 while the effect is off).
  void (*linear_values)(const EffectSet& effects, std::span<double> values);
  void (*scale_force)(EffectSet& effects, double force_scale);
  std::optional<std::string> (*implausible)(const EffectSet& effects, const RunScales& scales);
  std::vector<std::pair<std::string, double>> (*report)(const EffectSet& effects);
  // Whether the two sets hold the same parameters for this effect.
  bool (*same)(const EffectSet& a, const EffectSet& b);
  // The simulator: the effect's size-1 parameters on a damper class into `nominal` (off);
  // `nominal`'s parameters for this effect at `size`, switched on, into `effects`.
  void (*set_nominal)(EffectSet& nominal, DamperClassId damper);
  void (*resize)(EffectSet& effects, const EffectSet& nominal, double size, double dissipated_energy);
  std::string (*size_summary)(const EffectSet& nominal);
};

// Every effect, in the list's order.
std::span<const EffectInfo> effect_infos();
// The effect called `name`; nullptr for an unknown name.
const EffectInfo* find_effect(std::string_view name);

}  // namespace mrd::model
