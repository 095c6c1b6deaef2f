#include "tools/simulation/damper_class.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "model/effects/effect_set.hpp"

namespace mrd::tools {

namespace {

// Every effect's size-1 parameters on the class, from its descriptor (off until a run asks).
model::EffectSet nominal_effects_of(model::DamperClassId damper) {
  model::EffectSet effects;
  for (const model::EffectInfo& e : model::effect_infos()) e.set_nominal(effects, damper);
  return effects;
}

}  // namespace

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
  c.nominal_effects = nominal_effects_of(model::DamperClassId::k50kN);
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
  c.nominal_effects = nominal_effects_of(model::DamperClassId::k1kN);
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
  const model::EffectInfo* known = model::find_effect(request.name);
  if (known == nullptr || !known->named_candidate) {
    error = "unknown effect '" + request.name + "'; known: ";
    for (const model::EffectInfo& e : model::effect_infos())
      if (e.named_candidate) error += std::string(e.name) + " ";
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

void apply_effect(const DamperClass& c, const EffectRequest& r, double dissipated_energy, model::EffectSet& e) {
  if (const model::EffectInfo* effect = model::find_effect(r.name)) {
    effect->resize(e, c.nominal_effects, r.size, dissipated_energy);
  }
}

}  // namespace mrd::tools
