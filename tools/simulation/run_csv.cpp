#include "tools/simulation/run_csv.hpp"

#include <cstdio>

#include "config/effects_config.hpp"
#include "tools/json.hpp"

namespace mrd::tools {

namespace {

std::string csv_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", value);
  return buffer;
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
    row = csv_number(s.time) + ',' + csv_number(s.displacement * 1e3) + ',' +
          csv_number(s.current) + ',' + csv_number(s.force * 1e-3);
    if (columns.velocity) row += ',' + csv_number(s.velocity * 1e3);
    if (columns.B) row += ',' + csv_number(s.B);
    if (columns.temperature) row += ',' + csv_number(s.temperature);
    row += '\n';
    out << row;
  }
}

std::string run_manifest_json(const SimulatedRun& run) {
  const RunOptions& o = run.options;
  std::string effects;
  for (const auto& e : o.effects) {
    effects += std::string(effects.empty() ? "" : ", ") + "{\"name\": " + json_string(e.name) +
               ", \"size\": " + json_number(e.size) + "}";
  }
  return "{\n  \"damper_class\": " + json_string(o.damper.name) + ",\n  \"profile\": " +
         json_string(to_string(o.profile)) + ",\n  \"rate_hz\": " + json_number(o.rate) +
         ",\n  \"duration_s\": " + json_number(o.duration) + ",\n  \"samples\": " +
         std::to_string(run.samples.size()) + ",\n  \"seed\": " + std::to_string(o.seed) +
         ",\n  \"lvdt_noise_m\": " + json_number(o.lvdt_noise) + ",\n  \"force_noise_N\": " +
         json_number(o.force_noise) + ",\n  \"effects\": [" + effects + "],\n  \"effects_toml\": " +
         json_string(config::effects_toml(run.effects)) + "\n}\n";
}

}  // namespace mrd::tools
