#include "tools/simulation/run_csv.hpp"


#include "config/effects_config.hpp"
#include "record/run_csv_writer.hpp"
#include "tools/json.hpp"

namespace mrd::tools {

void write_run_csv(std::ostream& out, const SimulatedRun& run, const RunColumns& columns) {
  const record::RunCsvWriter writer({.velocity = columns.velocity, .B = columns.B, .temperature = columns.temperature});
  out << writer.header();
  std::string rows;
  for (const RunSample& s : run.samples) {
    writer.append_row({s.time, s.displacement, s.current, s.force, s.velocity, s.B, s.temperature}, rows);
  }
  out << rows;
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
