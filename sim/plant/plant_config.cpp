#include "sim/plant/plant_config.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "config/config_loader.hpp"
#include "config/effects_config.hpp"
#include "config/toml_reader.hpp"
#include "hal/modbus/register_codec.hpp"

namespace mrd::plant {

namespace {

using config::TomlReader;

constexpr std::pair<std::string_view, FaultKind> kFaultNames[] = {
    {"frame_loss", FaultKind::kFrameLoss},
    {"delay", FaultKind::kDelay},
    {"bad_checksum", FaultKind::kBadChecksum},
    {"bad_counter", FaultKind::kBadCounter},
    {"lvdt_frozen", FaultKind::kLvdtFrozen},
    {"lvdt_out_of_range", FaultKind::kLvdtOutOfRange},
    {"lvdt_silent", FaultKind::kLvdtSilent},
    {"sensor_fault", FaultKind::kSensorFault},
    {"server_stall", FaultKind::kServerStall},
    {"server_restart", FaultKind::kServerRestart},
    {"error_frames", FaultKind::kErrorFrames},
    {"bus_off", FaultKind::kBusOff},
    {"driver_fault", FaultKind::kDriverFault},
    {"demand_stale", FaultKind::kDemandStale},
    {"demand_invalid", FaultKind::kDemandInvalid},
};

// The value a fault takes when the file leaves it at 0.
double default_value(FaultKind k) {
  switch (k) {
    case FaultKind::kFrameLoss: return 10.0;        // percent
    case FaultKind::kDelay: return 5e-3;            // s
    case FaultKind::kLvdtOutOfRange: return 0.060;  // m, past the default 50 mm limit
    case FaultKind::kErrorFrames: return 100.0;     // per second
    default: return 0.0;
  }
}

std::string resolve(const std::string& path, const std::string& file_name) {
  if (path.empty() || std::filesystem::path(path).is_absolute()) return path;
  const auto folder = std::filesystem::path(file_name).parent_path();
  return folder.empty() ? path : (folder / path).string();
}

void read_profile(TomlReader& in, ProfileConfig& p) {
  in.get_enum("profile.kind", p.kind,
              {{"sine", ProfileKind::kSine}, {"sines", ProfileKind::kSines},
               {"random", ProfileKind::kRandom}, {"playback", ProfileKind::kPlayback}});
  in.get("profile.amplitude", p.amplitude);
  in.get("profile.frequency", p.frequency);
  in.get("profile.frequencies", p.frequencies);
  in.get("profile.cycles", p.cycles);
  in.get("profile.random_low", p.random_low);
  in.get("profile.random_high", p.random_high);
  in.get("profile.random_length", p.random_length);
  in.get("profile.file", p.file);
}

void read_faults(const toml::table& root, TomlReader& in, std::vector<Fault>& faults) {
  const toml::table* table = root["faults"].as_table();
  if (table == nullptr) {
    if (root.contains("faults")) in.error("faults", "must be a table of [faults.<name>] tables");
    return;
  }
  for (auto&& [key, node] : *table) {
    Fault f;
    f.name = std::string(key.str());
    const std::string at = "faults." + f.name;
    if (f.name.find('.') != std::string::npos || !node.is_table()) {
      in.error(at, "must be a table [faults.<name>] with a name without dots");
      continue;
    }
    std::string kind;
    in.get(at + ".kind", kind);
    in.get(at + ".start", f.start);
    in.get(at + ".duration", f.duration);
    in.get(at + ".value", f.value);
    f.kind = FaultKind::kCount;
    for (const auto& [name, k] : kFaultNames) {
      if (name == kind) f.kind = k;
    }
    if (f.kind == FaultKind::kCount) {
      std::string names;
      for (const auto& [name, k] : kFaultNames) names += (names.empty() ? "" : ", ") + std::string(name);
      in.error(at + ".kind", "must be one of " + names + ", got \"" + kind + "\"");
      continue;
    }
    if (f.value == 0.0) f.value = default_value(f.kind);
    if (!(f.start >= 0.0)) in.error(at + ".start", "must be >= 0 s");
    if (!(f.duration >= 0.0)) in.error(at + ".duration", "must be >= 0 s (0: to the end)");
    if (f.kind == FaultKind::kFrameLoss && !(f.value > 0.0 && f.value <= 100.0)) {
      in.error(at + ".value", "must be a percentage in (0, 100]");
    }
    if (f.kind == FaultKind::kDelay && !(f.value > 0.0 && f.value <= 1.0)) {
      in.error(at + ".value", "must be a delay in (0, 1] s");
    }
    if (f.kind == FaultKind::kErrorFrames && !(f.value > 0.0 && f.value <= 10000.0)) {
      in.error(at + ".value", "must be a rate in (0, 10000] frames per second");
    }
    faults.push_back(std::move(f));
  }
}

void read_all(const toml::table& root, TomlReader& in, PlantConfig& c, const std::string& file) {
  in.get("plant.rate", c.rate);
  in.get("plant.duration", c.duration);
  in.get("plant.controller_config", c.controller_config);
  in.get("plant.lvdt_noise", c.lvdt_noise);
  in.get("plant.force_noise", c.force_noise);
  in.get("plant.demand_damping", c.demand_damping);
  in.get("plant.seed", c.seed);
  in.get("plant.log", c.log);
  in.get_enum("plant.faults_from", c.faults_from,
              {{"first_command", FaultClock::kFirstCommand}, {"start", FaultClock::kStart}});
  in.get("realtime.priority", c.realtime.priority);
  in.get("realtime.cpu", c.realtime.cpu);
  in.get("realtime.lock_memory", c.realtime.lock_memory);
  in.get("realtime.io_priority", c.realtime.io_priority);
  in.get("realtime.cpu_dma_latency", c.realtime.cpu_dma_latency);
  read_profile(in, c.profile);
  in.get("modbus.enabled", c.modbus.enabled);
  in.get("modbus.listen", c.modbus.listen);
  in.get("modbus.port", c.modbus.port);
  in.get("modbus.rtu_link", c.modbus.rtu_link);
  in.get("can.enabled", c.can.enabled);
  in.get("can.interface", c.can.interface);
  in.get("can.feedback", c.can.feedback);
  in.get("can.fault_pull", c.can.fault_pull);
  config::read_effects(in, c.effects);
  read_faults(root, in, c.faults);
  c.controller_config = resolve(c.controller_config, file);
  c.profile.file = resolve(c.profile.file, file);
}

void validate(TomlReader& in, const PlantConfig& c) {
  if (!(c.rate >= 10.0 && c.rate <= 20000.0)) in.error("plant.rate", "must be in 10..20000 Hz");
  if (!(c.duration >= 0.0)) in.error("plant.duration", "must be >= 0 s (0: the profile's length)");
  if (!(c.lvdt_noise >= 0.0)) in.error("plant.lvdt_noise", "must be >= 0 m");
  if (!(c.force_noise >= 0.0)) in.error("plant.force_noise", "must be >= 0 N");
  if (!(c.demand_damping >= 0.0 && std::isfinite(c.demand_damping))) {
    in.error("plant.demand_damping", "must be a finite value >= 0 N s/m");
  }
  const ValidationReport realtime = c.realtime.validate();
  for (const auto& problem : realtime.issues()) {
    in.error("realtime." + problem.field, problem.message);
  }
  const auto& p = c.profile;
  if (!(p.amplitude > 0.0 && p.amplitude <= 1.0)) in.error("profile.amplitude", "must be in (0, 1] m");
  if (!(p.frequency > 0.0 && p.frequency <= 100.0)) in.error("profile.frequency", "must be in (0, 100] Hz");
  for (std::size_t i = 0; i < p.frequencies.size(); ++i) {
    if (!(p.frequencies[i] > 0.0 && p.frequencies[i] <= 100.0)) {
      in.error("profile.frequencies[" + std::to_string(i) + "]", "must be in (0, 100] Hz");
    }
  }
  if (p.cycles < 1) in.error("profile.cycles", "must be >= 1");
  if (!(p.random_low > 0.0 && p.random_low < p.random_high)) {
    in.error("profile.random_low", "must be > 0 Hz and below profile.random_high");
  }
  if (!(p.random_high < c.rate / 4.0)) in.error("profile.random_high", "must be below a quarter of plant.rate");
  if (!(p.random_length > 0.0)) in.error("profile.random_length", "must be > 0 s");
  if (p.kind == ProfileKind::kPlayback && p.file.empty()) {
    in.error("profile.file", "a playback profile needs a recorded run");
  }
  if (c.modbus.port < -1 || c.modbus.port > 65535) in.error("modbus.port", "must be -1, 0 or a TCP port");
  if (!c.modbus.enabled && !c.can.enabled) {
    in.warning("modbus.enabled", "neither Modbus nor CAN is on: the plant serves nobody");
  }
  const ValidationReport effects = model::validate(c.effects);
  for (const auto& issue : effects.issues()) {
    const std::string key = "damper.effects." + issue.field;
    issue.severity == ValidationIssue::Severity::kError ? in.error(key, issue.message)
                                                              : in.warning(key, issue.message);
  }
}

// demand_invalid's value is a demand beyond the controller's force.demand_range (by default
// twice it), one its demand registers can carry: a value the controller takes as fair, or the
// codec refuses (the registers would keep the last good one), would inject no fault.
// A demand fault the plant cannot inject is an error, not a script that silently tests nothing:
// without a demand sent on a bus, or, over Modbus, a stale demand without the counter that
// makes it visible.
void check_demand_faults(TomlReader& in, PlantConfig& c) {
  const double range = c.controller.safety.demand_range;
  const auto& registers = c.controller.modbus.registers;
  for (Fault& f : c.faults) {
    if (f.kind != FaultKind::kDemandInvalid && f.kind != FaultKind::kDemandStale) continue;
    const std::string kind_key = "faults." + f.name + ".kind";
    if (!c.sends_demand()) {
      in.error(kind_key, "the plant sends no demand: it needs plant.demand_damping > 0 and a controller that "
                         "reads its demand from a bus");
      continue;
    }
    if (f.kind == FaultKind::kDemandStale) {
      if (registers.has_demand && !registers.has_demand_counter()) {
        in.error(kind_key, "over Modbus a stale demand is invisible without the controller's "
                           "modbus.registers.demand_counter_address");
      }
      continue;
    }
    const std::string key = "faults." + f.name + ".value";
    if (f.value == 0.0) f.value = 2.0 * range;
    if (!registers.has_demand) {
      continue;  // CAN: the frame's DemandInvalid bit; the value is not sent
    }
    if (!(std::fabs(f.value) > range)) {
      in.error(key, "must lie beyond the controller's force.demand_range (" + std::to_string(range) +
                        " N), or the controller takes it as a fair demand");
    } else if (hal::modbus::encode_register(f.value, registers.demand).status != hal::modbus::CodecStatus::kOk) {
      in.error(key, "cannot be written in the controller's demand registers (modbus.registers.demand)");
    }
  }
}

}  // namespace

std::string_view to_string(ProfileKind k) {
  switch (k) {
    case ProfileKind::kSine: return "sine";
    case ProfileKind::kSines: return "sines";
    case ProfileKind::kRandom: return "random";
    case ProfileKind::kPlayback: return "playback";
  }
  return "?";
}

std::string_view to_string(FaultKind k) {
  for (const auto& [name, kind] : kFaultNames) {
    if (kind == k) return name;
  }
  return "?";
}

model::DamperModel PlantConfig::truth() const {
  model::DamperModel d = controller.law.damper;
  d.effects = effects;
  return d;
}

std::string PlantConfig::listen_host() const {
  return modbus.listen.empty() ? controller.modbus.tcp.host : modbus.listen;
}

int PlantConfig::listen_port() const { return modbus.port < 0 ? controller.modbus.tcp.port : modbus.port; }

std::string PlantConfig::can_interface() const {
  return can.interface.empty() ? controller.can.interface : can.interface;
}

std::string LoadedPlantConfig::report() const {
  std::string out;
  for (const auto& m : errors) out += m.to_string() + '\n';
  for (const auto& m : warnings) out += m.to_string() + '\n';
  return out;
}

LoadedPlantConfig load_plant_config_text(std::string_view text, const std::string& file_name) {
  LoadedPlantConfig out;
  const std::optional<toml::table> root = config::parse_config_text(text, file_name, out.errors);
  if (!root) return out;
  config::ConfigMessages messages;
  TomlReader in(*root, file_name, messages);
  read_all(*root, in, out.config, file_name);
  in.report_unknown_keys();
  validate(in, out.config);

  // The controller's side of the buses and its damper.
  const auto controller = out.config.controller_config.empty()
                              ? config::load_default_config()
                              : config::load_config_file(out.config.controller_config);
  out.config.controller = controller.config;
  if (out.config.demand_damping > 0.0 && controller.ok() && !out.config.sends_demand()) {
    in.error("plant.demand_damping", "the controller config reads no demand from a bus: it needs control.mode = "
                                     "\"force\" and backends.demand = \"modbus\" or \"can\"");
  }
  if (controller.ok()) check_demand_faults(in, out.config);
  config::file_messages(messages, out.errors, out.warnings);
  for (const auto& m : controller.errors) out.errors.push_back(m);
  return out;
}

LoadedPlantConfig load_plant_config_file(const std::string& path) {
  LoadedPlantConfig out;
  const std::optional<std::string> text = config::read_config_file(path, out.errors);
  return text ? load_plant_config_text(*text, path) : out;
}

}  // namespace mrd::plant
