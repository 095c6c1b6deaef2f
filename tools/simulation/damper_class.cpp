#include "tools/simulation/damper_class.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "model/effects/effect_set.hpp"

namespace mrd::tools {

DamperClass damper_class_50kN() {
  DamperClass c;
  c.name = "50kN";
  // model: the defaults of docs/MODEL.md; schedule: Table 4 as published.
  c.amplitude = 0.040;
  c.max_current = 1.2;
  c.lvdt_noise = 5e-6;
  c.force_noise = 25.0;  // 0.05 % of the peak force
  c.random_low = 0.05;
  c.random_high = 1.0;
  c.coil_time_constant = 20e-3;  // a large coil: L/R of tens of ms
  c.preyield_travel = 0.5e-3;
  c.preyield_fraction = 0.1;
  c.gas_preload = 1500.0;
  c.gas_stiffness = 30e3;
  c.thermal_rise = 20.0;
  c.sensor_delay = 5e-3;
  c.stroke_end_threshold = 0.030;  // Section 4.3: 30-40 mm
  c.stroke_end_length = 5e-3;
  c.stroke_end_depth = 0.45;
  return c;
}

DamperClass damper_class_1kN() {
  DamperClass c;
  c.name = "1kN";
  // 40 mm piston with a 10 mm rod, two 4 mm poles, 1 mm gap, a 400-turn coil over a 40 mm path,
  // a 32 % fluid of 0.8 Pa s: yield force 1.4 kN at 1 A (B = 1.3 T), c0 = 850 N s/m. The J-A
  // material is the default's.
  c.model.circuit = {400.0, 0.04};
  c.model.fluid.viscosity = 0.8;
  c.model.fluid.volume_fraction = 0.32;
  c.model.geometry = {1.18e-3, 0.008, 1.0e-3, 0.04, 1e-3};
  c.schedule.thresholds = {0.0025, 0.005, 0.010, 0.015, 0.020};
  c.schedule.currents = {0.0, 0.15, 0.3, 0.5, 0.7, 1.0};
  c.schedule.band = 1e-4;
  c.amplitude = 0.020;
  c.max_current = 1.0;
  c.lvdt_noise = 2e-6;
  c.force_noise = 2.0;
  c.random_low = 0.1;
  c.random_high = 5.0;
  c.coil_time_constant = 1.0 / 190.0;  // Spencer 1997, Dyke's damper
  c.preyield_travel = 0.2e-3;
  c.preyield_fraction = 0.1;
  c.gas_preload = 70.0;                // Spencer's k1 x0 = 71.5 N
  c.gas_stiffness = 500.0;             // Spencer's k1
  c.thermal_rise = 20.0;
  c.sensor_delay = 1.5e-3;  // motion up to 5 Hz: a few ms is already a large phase error
  c.stroke_end_threshold = 0.015;
  c.stroke_end_length = 2.5e-3;
  c.stroke_end_depth = 0.45;
  return c;
}

std::optional<DamperClass> find_damper_class(std::string_view name) {
  if (name == "50kN") return damper_class_50kN();
  if (name == "1kN") return damper_class_1kN();
  return std::nullopt;
}

std::optional<EffectRequest> parse_effect_request(std::string_view text, std::string& error) {
  const auto colon = text.find(':');
  EffectRequest request{std::string(text.substr(0, colon)), 1.0};
  if (std::find(model::kEffectNames.begin(), model::kEffectNames.end(), request.name) ==
      model::kEffectNames.end()) {
    error = "unknown effect '" + request.name + "'; known: ";
    for (const auto name : model::kEffectNames) error += std::string(name) + " ";
    return std::nullopt;
  }
  if (colon == std::string_view::npos) return request;
  const std::string_view size = text.substr(colon + 1);
  if (size == "small") {
    request.size = 0.5;
  } else if (size == "medium") {
    request.size = 1.0;
  } else if (size == "large") {
    request.size = 2.0;
  } else {
    const auto [end, ec] = std::from_chars(size.data(), size.data() + size.size(), request.size);
    if (ec != std::errc{} || end != size.data() + size.size() || !(request.size > 0.0) ||
        !std::isfinite(request.size)) {
      error = "effect size '" + std::string(size) + "' must be small, medium, large or a number > 0";
      return std::nullopt;
    }
  }
  return request;
}

void apply_effect(const DamperClass& c, const EffectRequest& r, double dissipated_energy,
                  model::EffectSet& e) {
  const double s = r.size;
  if (r.name == "coil_lag") {
    e.coil_lag = {true, s * c.coil_time_constant};
  } else if (r.name == "preyield_hysteresis") {
    const double z_max = c.preyield_travel;
    e.preyield_hysteresis.enabled = true;
    e.preyield_hysteresis.A = 1.0;
    e.preyield_hysteresis.n = 2.0;
    e.preyield_hysteresis.beta = 0.5 / (z_max * z_max);  // (A / (beta + gamma))^(1/2) = z_max
    e.preyield_hysteresis.gamma = e.preyield_hysteresis.beta;
    e.preyield_hysteresis.yield_fraction = std::min(s * c.preyield_fraction, 1.0);
  } else if (r.name == "gas_spring") {
    e.gas_spring = {true, s * c.gas_preload, s * c.gas_stiffness};
  } else if (r.name == "thermal_drift") {
    e.thermal_drift.enabled = true;
    e.thermal_drift.heat_capacity = std::max(dissipated_energy, 1.0) / (s * c.thermal_rise);
  } else if (r.name == "sensor_delay") {
    e.sensor_delay = {true, std::min(s * c.sensor_delay, model::kMaxSensorDelay)};
  } else if (r.name == "stroke_end_air") {
    e.stroke_end_air.enabled = true;
    e.stroke_end_air.threshold = c.stroke_end_threshold;
    e.stroke_end_air.length = c.stroke_end_length;
    e.stroke_end_air.depth = std::min(s * c.stroke_end_depth, 0.95);
  }
}

}  // namespace mrd::tools
