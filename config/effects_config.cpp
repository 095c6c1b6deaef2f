#include "config/effects_config.hpp"

#include <charconv>
#include <initializer_list>
#include <string>
#include <type_traits>
#include <utility>

namespace mrd::config {

namespace {

using model::TemperatureLaw;

constexpr std::string_view kPrefix = "damper.effects.";

const std::initializer_list<std::pair<std::string_view, TemperatureLaw>> kLaws = {
    {"linear", TemperatureLaw::kLinear}, {"exponential", TemperatureLaw::kExponential}};

// Calls `v(table, key, field)` for every key of every effect, in file order. `field` is a
// double, int, bool or TemperatureLaw.
template <typename Visitor>
void visit(model::EffectSet& e, Visitor&& v) {
  v("coil_lag", "enabled", e.coil_lag.enabled);
  v("coil_lag", "time_constant", e.coil_lag.time_constant);
  auto& p = e.preyield_hysteresis;
  v("preyield_hysteresis", "enabled", p.enabled);
  v("preyield_hysteresis", "A", p.A);
  v("preyield_hysteresis", "beta", p.beta);
  v("preyield_hysteresis", "gamma", p.gamma);
  v("preyield_hysteresis", "n", p.n);
  v("preyield_hysteresis", "stiffness", p.stiffness);
  v("preyield_hysteresis", "yield_fraction", p.yield_fraction);
  v("preyield_hysteresis", "max_substeps", p.max_substeps);
  v("gas_spring", "enabled", e.gas_spring.enabled);
  v("gas_spring", "preload", e.gas_spring.preload);
  v("gas_spring", "stiffness", e.gas_spring.stiffness);
  auto& t = e.thermal_drift;
  v("thermal_drift", "enabled", t.enabled);
  v("thermal_drift", "initial_temperature", t.initial_temperature);
  v("thermal_drift", "ambient_temperature", t.ambient_temperature);
  v("thermal_drift", "reference_temperature", t.reference_temperature);
  v("thermal_drift", "heat_capacity", t.heat_capacity);
  v("thermal_drift", "cooling_time_constant", t.cooling_time_constant);
  v("thermal_drift", "viscosity_law", t.viscosity_law);
  v("thermal_drift", "viscosity_coefficient", t.viscosity_coefficient);
  v("thermal_drift", "yield_law", t.yield_law);
  v("thermal_drift", "yield_coefficient", t.yield_coefficient);
  v("thermal_drift", "min_factor", t.min_factor);
  v("sensor_delay", "enabled", e.sensor_delay.enabled);
  v("sensor_delay", "delay", e.sensor_delay.delay);
  auto& s = e.stroke_end_air;
  v("stroke_end_air", "enabled", s.enabled);
  v("stroke_end_air", "threshold", s.threshold);
  v("stroke_end_air", "depth", s.depth);
  v("stroke_end_air", "length", s.length);
  v("stroke_end_air", "reversal_travel", s.reversal_travel);
}

struct Reader {
  TomlReader& in;
  template <typename T>
  void operator()(std::string_view table, std::string_view key, T& field) {
    std::string path(kPrefix);
    path.append(table).append(".").append(key);
    if constexpr (std::is_same_v<T, TemperatureLaw>) {
      in.get_enum(path, field, kLaws);
    } else {
      in.get(path, field);
    }
  }
};

// The shortest text that reads back as the same double, with a '.' or an exponent so that TOML
// sees a float.
std::string format_double(double value) {
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf, value).ptr;
  std::string text(buf, end);
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";  // 'n': nan, inf
  return text;
}

struct Writer {
  std::string out;
  std::string_view table;
  template <typename T>
  void operator()(std::string_view t, std::string_view key, const T& field) {
    if (t != table) {
      if (!out.empty()) out += '\n';
      out.append("[").append(kPrefix).append(t).append("]\n");
      table = t;
    }
    out.append(key).append(" = ");
    if constexpr (std::is_same_v<T, bool>) {
      out += field ? "true" : "false";
    } else if constexpr (std::is_same_v<T, int>) {
      out += std::to_string(field);
    } else if constexpr (std::is_same_v<T, TemperatureLaw>) {
      for (const auto& [name, law] : kLaws) {
        if (law == field) out.append("\"").append(name).append("\"");
      }
    } else {
      out += format_double(field);
    }
    out += '\n';
  }
};

}  // namespace

void read_effects(TomlReader& in, model::EffectSet& effects) { visit(effects, Reader{in}); }

std::string effects_toml(const model::EffectSet& effects) {
  model::EffectSet copy = effects;  // visit() hands out mutable fields; the writer only reads
  Writer writer;
  visit(copy, writer);
  return writer.out;
}

}  // namespace mrd::config
