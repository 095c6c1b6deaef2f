#include "sim/plant/plant_command.hpp"

#include <cstdio>
#include <memory>
#include <optional>

#include "common/cli/exit_code.hpp"
#include "record/csv.hpp"
#include "sim/plant/plant_config.hpp"
#include "sim/plant/plant_run.hpp"
#include "sim/plant/rig.hpp"

namespace mrd::plant {

namespace {

int check_config(const std::string& path) {
  const auto loaded = load_plant_config_file(path);
  std::fputs(loaded.report().c_str(), loaded.ok() ? stdout : stderr);
  if (loaded.ok()) std::printf("%s: ok\n", path.c_str());
  return loaded.ok() ? cli::kOk : cli::kUsage;
}

void apply_overrides(const PlantCommand& command, PlantConfig& config) {
  if (command.duration >= 0.0) config.duration = command.duration;
  if (command.port >= 0) config.modbus.port = command.port;
  if (!command.log_path.empty()) config.log = command.log_path;
  if (command.no_log) config.log.clear();
}

// The config file with the command line's overrides; nullopt, its problems printed, when invalid.
std::optional<PlantConfig> load_config(const PlantCommand& command) {
  if (command.config_path.empty()) {
    std::fprintf(stderr, "mrd-plant: --config FILE is required (etc/mrd/plant.toml lists every key)\n");
    return std::nullopt;
  }
  const auto loaded = load_plant_config_file(command.config_path);
  std::fputs(loaded.report().c_str(), loaded.ok() ? stdout : stderr);
  if (!loaded.ok()) {
    std::fprintf(stderr, "%s: %zu error(s)\n", command.config_path.c_str(), loaded.errors.size());
    return std::nullopt;
  }
  PlantConfig config = loaded.config;
  apply_overrides(command, config);
  return config;
}

// The rig on the config's motion; an endless duration becomes a playback's length. Null, the
// reason printed, when the playback file cannot be read.
std::unique_ptr<Rig> make_rig(PlantConfig& config) {
  try {
    auto motion = make_motion(config);
    if (config.duration == 0.0) config.duration = motion.duration();
    return std::make_unique<Rig>(config, std::move(motion));
  } catch (const record::InputError& e) {
    std::fprintf(stderr, "mrd-plant: profile.file: %s\n", e.what());
    return nullptr;
  }
}

}  // namespace

int run_command(const PlantCommand& command, runtime::ProcessSignals& signals) {
  if (!command.check_path.empty()) return check_config(command.check_path);
  auto config = load_config(command);
  if (!config) return cli::kUsage;
  const std::unique_ptr<Rig> rig = make_rig(*config);
  if (!rig) return cli::kBadInput;
  // Before the bus threads start, so they inherit a mask without the signals.
  const sigset_t mask = runtime::install_process_signals(signals);
  return run_plant(*config, *rig, signals, &mask);
}

}  // namespace mrd::plant
