#include "tools/simulation/run_csv.hpp"

#include <cstdio>

#include "firmware/effects_config.hpp"

namespace mrd::tools {

namespace {

std::string number(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", value);
  return buf;
}

std::string json_string(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace

void write_run_csv(std::ostream& out, const SimulatedRun& run, const RunColumns& columns) {
  out << "time_s,displacement_mm,current_A,force_kN";
  if (columns.velocity) out << ",velocity_mm_s";
  if (columns.B) out << ",B_T";
  if (columns.temperature) out << ",temperature_C";
  out << '\n';
  std::string row;
  for (const RunSample& s : run.samples) {
    row = number(s.time) + ',' + number(s.displacement * 1e3) + ',' + number(s.current) + ',' +
          number(s.force * 1e-3);
    if (columns.velocity) row += ',' + number(s.velocity * 1e3);
    if (columns.B) row += ',' + number(s.B);
    if (columns.temperature) row += ',' + number(s.temperature);
    row += '\n';
    out << row;
  }
}

std::string run_manifest_json(const SimulatedRun& run) {
  const RunOptions& o = run.options;
  std::string effects;
  for (const auto& e : o.effects) {
    effects += std::string(effects.empty() ? "" : ", ") + "{\"name\": " + json_string(e.name) +
               ", \"size\": " + number(e.size) + "}";
  }
  return "{\n  \"damper_class\": " + json_string(o.damper.name) + ",\n  \"profile\": " +
         json_string(to_string(o.profile)) + ",\n  \"rate_hz\": " + number(o.rate) +
         ",\n  \"duration_s\": " + number(o.duration) + ",\n  \"samples\": " +
         std::to_string(run.samples.size()) + ",\n  \"seed\": " + std::to_string(o.seed) +
         ",\n  \"lvdt_noise_m\": " + number(o.lvdt_noise) + ",\n  \"force_noise_N\": " +
         number(o.force_noise) + ",\n  \"effects\": [" + effects + "],\n  \"effects_toml\": " +
         json_string(firmware::effects_toml(run.effects)) + "\n}\n";
}

}  // namespace mrd::tools
