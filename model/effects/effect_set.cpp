#include "model/effects/effect_set.hpp"

namespace mrd::model {

bool* enabled_flag(EffectSet& e, std::string_view name) {
  if (name == "coil_lag") return &e.coil_lag.enabled;
  if (name == "preyield_hysteresis") return &e.preyield_hysteresis.enabled;
  if (name == "gas_spring") return &e.gas_spring.enabled;
  if (name == "thermal_drift") return &e.thermal_drift.enabled;
  if (name == "sensor_delay") return &e.sensor_delay.enabled;
  if (name == "stroke_end_air") return &e.stroke_end_air.enabled;
  return nullptr;
}

bool is_enabled(const EffectSet& effects, std::string_view name) {
  EffectSet copy = effects;
  const bool* flag = enabled_flag(copy, name);
  return flag != nullptr && *flag;
}

ValidationReport validate(const EffectSet& e) {
  ValidationReport report;
  report.merge(validate(e.coil_lag), "coil_lag");
  report.merge(validate(e.preyield_hysteresis), "preyield_hysteresis");
  report.merge(validate(e.gas_spring), "gas_spring");
  report.merge(validate(e.thermal_drift), "thermal_drift");
  report.merge(validate(e.sensor_delay), "sensor_delay");
  report.merge(validate(e.stroke_end_air), "stroke_end_air");
  return report;
}

}  // namespace mrd::model
