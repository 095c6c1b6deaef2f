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
  Json effects = Json::array();
  for (const auto& e : o.effects) effects.push_back({{"name", e.name}, {"size", e.size}});
  return json_text({{"damper_class", o.damper.name},
                    {"profile", std::string(to_string(o.profile))},
                    {"rate_hz", o.rate},
                    {"duration_s", o.duration},
                    {"samples", run.samples.size()},
                    {"seed", o.seed},
                    {"lvdt_noise_m", o.lvdt_noise},
                    {"force_noise_N", o.force_noise},
                    {"effects", effects},
                    {"effects_toml", config::effects_toml(run.effects)}});
}

}  // namespace mrd::tools
