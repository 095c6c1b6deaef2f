#pragma once

#include <array>
#include <string_view>

#include "model/effects/coil_lag.hpp"
#include "model/effects/gas_spring.hpp"
#include "model/effects/preyield_hysteresis.hpp"
#include "model/effects/sensor_delay.hpp"
#include "model/effects/stroke_end_air.hpp"
#include "model/effects/thermal_drift.hpp"
#include "common/validation_report.hpp"

namespace mrd::model {

// The optional effects the base J-A + Bingham model lacks, each switched on and sized on its
// own (docs/MODEL.md, "Optional effects"). All are off by default, and then the observer runs
// exactly the base model.
struct EffectSet {
  CoilLagParams coil_lag;
  PreyieldHysteresisParams preyield_hysteresis;
  GasSpringParams gas_spring;
  ThermalDriftParams thermal_drift;
  SensorDelayParams sensor_delay;
  StrokeEndAirParams stroke_end_air;

  [[nodiscard]] bool any_enabled() const {
    return coil_lag.enabled || preyield_hysteresis.enabled || gas_spring.enabled ||
           thermal_drift.enabled || sensor_delay.enabled || stroke_end_air.enabled;
  }
};

// The effects' names, as the config tables ([damper.effects.<name>]), the tools and the reports
// spell them, in the order the observer applies them.
inline constexpr std::array<std::string_view, 6> kEffectNames = {
    "sensor_delay", "coil_lag", "thermal_drift", "preyield_hysteresis", "stroke_end_air", "gas_spring"};

// The enabled flag of the effect called `name`; nullptr for an unknown name.
bool* enabled_flag(EffectSet& effects, std::string_view name);
[[nodiscard]] bool is_enabled(const EffectSet& effects, std::string_view name);

// Every effect's parameters, enabled or not (a disabled table with a bad value is still a bad
// file), with field paths such as "coil_lag.time_constant".
ValidationReport validate(const EffectSet& effects);

}  // namespace mrd::model
