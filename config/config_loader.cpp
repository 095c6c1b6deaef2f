#include "config/config_loader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "config/default_config_text.hpp"  // generated from etc/mrd/mrd.toml
#include "config/effects_config.hpp"
#include "config/toml_reader.hpp"

namespace mrd::config {

std::string_view to_string(DeviceBackend b) {
  switch (b) {
    case DeviceBackend::kMock: return "mock";
    case DeviceBackend::kModbus: return "modbus";
    case DeviceBackend::kCan: return "can";
  }
  return "?";
}

std::string_view to_string(LinesBackend b) { return b == LinesBackend::kGpio ? "gpio" : "mock"; }

ValidationReport SimulationConfig::validate() const {
  ValidationReport r;
  r.check(std::isfinite(amplitude) && amplitude >= 0.0, "amplitude", "must be a finite value >= 0 m");
  r.check(std::isfinite(frequency) && frequency > 0.0, "frequency", "must be a finite value > 0 Hz");
  r.check(std::isfinite(lvdt_noise) && lvdt_noise >= 0.0, "lvdt_noise", "must be a finite value >= 0 m");
  r.check(std::isfinite(demand_damping) && demand_damping >= 0.0, "demand_damping",
          "must be a finite value >= 0 N s/m");
  return r;
}

std::string LoadedConfig::report() const {
  std::string out;
  for (const auto& m : errors) out += m.to_string() + '\n';
  for (const auto& m : warnings) out += m.to_string() + '\n';
  return out;
}

namespace {

using hal::modbus::ByteOrder;
using hal::modbus::RegisterFormat;
using hal::modbus::RegisterKind;
using hal::modbus::RegisterType;
using hal::modbus::WordOrder;

void read_format(TomlReader& in, const std::string& at, RegisterFormat& f) {
  in.get_enum(at + ".type", f.type,
              {{"int16", RegisterType::kInt16}, {"uint16", RegisterType::kUint16},
               {"int32", RegisterType::kInt32}, {"uint32", RegisterType::kUint32},
               {"float32", RegisterType::kFloat32}});
  in.get_enum(at + ".word_order", f.word_order,
              {{"high_first", WordOrder::kHighFirst}, {"low_first", WordOrder::kLowFirst}});
  in.get_enum(at + ".byte_order", f.byte_order,
              {{"normal", ByteOrder::kNormal}, {"swapped", ByteOrder::kSwapped}});
  in.get(at + ".scale", f.scale);
  in.get(at + ".offset", f.offset);
}

void read_kind(TomlReader& in, const std::string& at, RegisterKind& kind) {
  in.get_enum(at, kind, {{"input", RegisterKind::kInput}, {"holding", RegisterKind::kHolding}});
}

void read_modbus(TomlReader& in, hal::modbus::ModbusConfig& m) {
  in.get_enum("modbus.transport", m.transport,
              {{"tcp", hal::modbus::Transport::kTcp}, {"rtu", hal::modbus::Transport::kRtu}});
  in.get("modbus.slave_id", m.slave_id);
  in.get_seconds("modbus.response_timeout", m.response_timeout);
  in.get_seconds("modbus.byte_timeout", m.byte_timeout);
  in.get_seconds("modbus.poll_period", m.poll_period);
  in.get_seconds("modbus.reconnect_min", m.reconnect_min);
  in.get_seconds("modbus.reconnect_max", m.reconnect_max);
  in.get("modbus.tcp.host", m.tcp.host);
  in.get("modbus.tcp.port", m.tcp.port);
  in.get("modbus.rtu.device", m.rtu.device);
  in.get("modbus.rtu.baud", m.rtu.baud);
  in.get("modbus.rtu.parity", m.rtu.parity);
  in.get("modbus.rtu.data_bits", m.rtu.data_bits);
  in.get("modbus.rtu.stop_bits", m.rtu.stop_bits);
  auto& r = m.registers;
  in.get("modbus.registers.lvdt_address", r.lvdt_address);
  read_kind(in, "modbus.registers.lvdt_kind", r.lvdt_kind);
  read_format(in, "modbus.registers.lvdt", r.lvdt);
  in.get("modbus.registers.setpoint_address", r.setpoint_address);
  read_format(in, "modbus.registers.setpoint", r.setpoint);
  in.get("modbus.registers.has_current_feedback", r.has_current_feedback);
  in.get("modbus.registers.current_feedback_address", r.current_feedback_address);
  read_kind(in, "modbus.registers.current_feedback_kind", r.current_feedback_kind);
  read_format(in, "modbus.registers.current_feedback", r.current_feedback);
  in.get("modbus.registers.demand_address", r.demand_address);
  read_kind(in, "modbus.registers.demand_kind", r.demand_kind);
  read_format(in, "modbus.registers.demand", r.demand);
  in.get("modbus.registers.demand_counter_address", r.demand_counter_address);
  in.get("modbus.registers.load_cell_address", r.load_cell_address);
  read_kind(in, "modbus.registers.load_cell_kind", r.load_cell_kind);
  read_format(in, "modbus.registers.load_cell", r.load_cell);
}

void read_can(TomlReader& in, hal::can::SocketCanConfig& c) {
  in.get("can.interface", c.interface);
  in.get("can.extended_ids", c.extended_ids);
  in.get("can.lvdt_id", c.lvdt_id);
  in.get("can.command_id", c.command_id);
  in.get("can.use_feedback", c.use_feedback);
  in.get("can.feedback_id", c.feedback_id);
  in.get("can.demand_id", c.demand_id);
  in.get("can.load_cell_id", c.load_cell_id);
  in.get_seconds("can.receive_timeout", c.receive_timeout);
  in.get_seconds("can.bus_off_hold_off", c.bus_off_hold_off);
}

void read_gpio(TomlReader& in, hal::gpio::GpioConfig& g) {
  in.get("gpio.chip", g.chip);
  in.get("gpio.consumer_prefix", g.consumer_prefix);
  for (auto [name, line] : {std::pair{"enable", &g.enable}, std::pair{"fault", &g.fault},
                            std::pair{"heartbeat", &g.heartbeat}}) {
    in.get(std::string("gpio.") + name + ".offset", line->offset);
    in.get(std::string("gpio.") + name + ".active_low", line->active_low);
  }
}

void read_damper(TomlReader& in, model::DamperModel& d) {
  in.get("damper.jiles_atherton.Ms", d.jiles_atherton.Ms);
  in.get("damper.jiles_atherton.a", d.jiles_atherton.a);
  in.get("damper.jiles_atherton.alpha", d.jiles_atherton.alpha);
  in.get("damper.jiles_atherton.k", d.jiles_atherton.k);
  in.get("damper.jiles_atherton.c", d.jiles_atherton.c);
  in.get("damper.circuit.turns", d.circuit.turns);
  in.get("damper.circuit.effective_length", d.circuit.effective_length);
  in.get_enum("damper.integration.integrator", d.integration.integrator,
              {{"rk4", model::Integrator::kRk4}, {"heun", model::Integrator::kHeun}});
  in.get("damper.integration.max_field_step_fraction", d.integration.max_field_step_fraction);
  in.get("damper.integration.max_substeps", d.integration.max_substeps);
  in.get("damper.integration.denominator_floor", d.integration.denominator_floor);
  in.get("damper.fluid.viscosity", d.fluid.viscosity);
  in.get("damper.fluid.volume_fraction", d.fluid.volume_fraction);
  in.get("damper.fluid.particle_diameter", d.fluid.particle_diameter);
  in.get("damper.fluid.particle_saturation", d.fluid.particle_saturation);
  in.get("damper.fluid.field_exponent", d.fluid.field_exponent);
  in.get("damper.fluid.flow_index", d.fluid.flow_index);
  in.get("damper.fluid.saturation_induction", d.fluid.saturation_induction);
  in.get("damper.fluid.saturation_shape", d.fluid.saturation_shape);
  in.get("damper.geometry.piston_area", d.geometry.piston_area);
  in.get("damper.geometry.pole_length", d.geometry.pole_length);
  in.get("damper.geometry.gap", d.geometry.gap);
  in.get("damper.geometry.piston_diameter", d.geometry.piston_diameter);
  in.get("damper.geometry.sign_velocity_scale", d.geometry.sign_velocity_scale);
  in.get("damper.geometry.sign_shape", d.geometry.sign_shape);
  in.get("damper.geometry.seal_friction", d.geometry.seal_friction);
  read_effects(in, d.effects);
}

void read_law(TomlReader& in, control::ControlLawConfig& law) {
  in.get_enum("control.mode", law.mode,
              {{"table4", control::ControlMode::kTable4}, {"force", control::ControlMode::kForce}});
  in.get("force.invert_coil_lag", law.force.invert_coil_lag);
  in.get("force.load_cell.time_constant", law.load_cell.time_constant);
  in.get("force.load_cell.max_correction", law.load_cell.max_correction);
  in.get("force.load_cell.min_force_fraction", law.load_cell.min_force_fraction);
  in.get("force.load_cell.min_speed", law.load_cell.min_speed);
  in.get("force.load_cell.max_age", law.load_cell.max_age_periods);
  read_damper(in, law.damper);
  in.get("schedule.thresholds", law.schedule.thresholds);
  in.get("schedule.currents", law.schedule.currents);
  in.get("schedule.band", law.schedule.band);
  in.get("compensator.enabled", law.compensate_hysteresis);
  in.get_enum("compensator.target", law.target,
              {{"anhysteretic", model::TargetCurve::Kind::kAnhysteretic},
               {"initial", model::TargetCurve::Kind::kInitial}});
  in.get("compensator.min_current", law.limits.min_current);
  in.get("compensator.max_current", law.limits.max_current);
  in.get("compensator.slew_rate", law.limits.slew_rate);
  in.get("compensator.tolerance", law.limits.tolerance);
  in.get("compensator.max_iterations", law.limits.max_iterations);
  in.get("observer.velocity_cutoff_frequency", law.observer.velocity_cutoff_frequency);
}

void read_safety(TomlReader& in, control::SupervisorConfig& s) {
  in.get("safety.displacement_min", s.displacement_min);
  in.get("safety.displacement_max", s.displacement_max);
  in.get("safety.stale_periods", s.stale_periods);
  in.get("safety.bad_sample_periods", s.bad_sample_periods);
  in.get("safety.frozen_periods", s.frozen_periods);
  in.get("safety.current_tolerance", s.current_tolerance);
  in.get("safety.current_disagreement_periods", s.current_disagreement_periods);
  in.get("safety.write_failure_periods", s.write_failure_periods);
  in.get("safety.readback_timeout_periods", s.readback_timeout_periods);
  in.get("safety.require_readback", s.require_readback);
  in.get("safety.line_failure_periods", s.line_failure_periods);
  in.get("safety.observer_recovery_periods", s.observer_recovery_periods);
  in.get("safety.max_speed", s.max_speed);
  in.get("safety.driver_fault_limit", s.driver_fault_limit);
  in.get("safety.driver_fault_window", s.driver_fault_window);
  in.get("safety.overrun_limit", s.overrun_limit);
  in.get("safety.overrun_window", s.overrun_window);
  in.get("safety.fail_safe_current", s.fail_safe_current);
  in.get("safety.enable_in_safe", s.enable_in_safe);
  in.get("safety.recovery_periods", s.recovery_periods);
  in.get("safety.degraded_clear_periods", s.degraded_clear_periods);
  in.get("safety.link_timeout", s.link_timeout);
  // Force mode's demand checks, judged by the supervisor as the LVDT's are.
  in.get("force.demand_range", s.demand_range);
  in.get("force.demand_max_age", s.demand_stale_periods);
}

void read_all(TomlReader& in, ControllerConfig& c) {
  in.get("loop.rate", c.rate);
  in.get_enum("backends.lvdt", c.backends.lvdt,
              {{"mock", DeviceBackend::kMock}, {"modbus", DeviceBackend::kModbus},
               {"can", DeviceBackend::kCan}});
  in.get_enum("backends.driver", c.backends.driver,
              {{"mock", DeviceBackend::kMock}, {"modbus", DeviceBackend::kModbus},
               {"can", DeviceBackend::kCan}});
  in.get_enum("backends.lines", c.backends.lines,
              {{"mock", LinesBackend::kMock}, {"gpio", LinesBackend::kGpio}});
  DeviceBackend demand = DeviceBackend::kMock;
  in.get_enum("backends.demand", demand,
              {{"mock", DeviceBackend::kMock}, {"modbus", DeviceBackend::kModbus},
               {"can", DeviceBackend::kCan}});
  // Force mode's optional load cell: none (the law runs open-loop on the model) by default.
  std::optional<DeviceBackend> load_cell;
  in.get_enum("backends.load_cell", load_cell,
              {{"none", std::nullopt}, {"mock", DeviceBackend::kMock}, {"modbus", DeviceBackend::kModbus},
               {"can", DeviceBackend::kCan}});
  in.get("simulation.amplitude", c.simulation.amplitude);
  in.get("simulation.frequency", c.simulation.frequency);
  in.get("simulation.lvdt_noise", c.simulation.lvdt_noise);
  in.get("simulation.seed", c.simulation.seed);
  in.get("simulation.demand_damping", c.simulation.demand_damping);
  read_modbus(in, c.modbus);
  read_can(in, c.can);
  read_gpio(in, c.gpio);
  read_law(in, c.law);
  // The demand channel is opened in force mode only: table4 reads none.
  if (c.law.mode == control::ControlMode::kForce) c.backends.demand = demand;
  c.can.use_demand = c.backends.demand == DeviceBackend::kCan;
  c.modbus.registers.has_demand = c.backends.demand == DeviceBackend::kModbus;
  if (c.law.mode == control::ControlMode::kForce) c.backends.load_cell = load_cell;
  c.law.has_load_cell = c.backends.load_cell.has_value();
  c.can.use_load_cell = c.backends.load_cell == DeviceBackend::kCan;
  c.modbus.registers.has_load_cell = c.backends.load_cell == DeviceBackend::kModbus;
  read_safety(in, c.safety);
  in.get("realtime.priority", c.realtime.priority);
  in.get("realtime.cpu", c.realtime.cpu);
  in.get("realtime.lock_memory", c.realtime.lock_memory);
  in.get("realtime.io_priority", c.realtime.io_priority);
  in.get("realtime.cpu_dma_latency", c.realtime.cpu_dma_latency);
  in.get("telemetry.path", c.telemetry.path);
  in.get("telemetry.directory", c.telemetry.directory);
  in.get("telemetry.decimation", c.telemetry.decimation);
  in.get("telemetry.ring_size", c.telemetry.ring_size);
  in.get("telemetry.flush_period", c.telemetry.flush_period);
  in.get("telemetry.per_run", c.telemetry.per_run);
  in.get("telemetry.max_bytes", c.telemetry.max_bytes);
}

void report(TomlReader& in, const ValidationReport& r, std::string_view table) {
  for (const auto& p : r.issues()) in.error(std::string(table) + "." + p.field, p.message);
}

// SupervisorConfig's demand fields come from the file's [force] table.
std::string safety_key(const std::string& field) {
  if (field == "demand_range") return "force.demand_range";
  if (field == "demand_stale_periods") return "force.demand_max_age";
  return "safety." + field;
}

// ControlLaw's validate() names its own struct fields; these are the keys the file uses.
std::string file_key(const std::string& field) {
  if (field.starts_with("limits.")) return "compensator." + field.substr(7);
  if (field == "observer.sample_period") return "loop.rate";
  if (field == "load_cell.max_age_periods") return "force.load_cell.max_age";
  if (field.starts_with("load_cell.")) return "force." + field;
  return field;
}

// Two values of the register map in the same registers would read each other's words: with the
// current feedback on the LVDT's registers, a negative displacement decodes as 65.5 mm minus its
// size (the feedback's word replaces the LVDT's high word).
void check_register_overlaps(TomlReader& in, const hal::modbus::RegisterMap& r) {
  struct Value {
    const char* key;   // the later value's address key, named in the error
    const char* what;  // the earlier value, as the error names it
    bool present;
    int address;
    RegisterKind kind;
    RegisterType type;
  };
  // In the order the errors name them: each value is checked against those before it.
  const std::array<Value, 6> values{{
      {"modbus.registers.lvdt_address", "the LVDT's registers", true, r.lvdt_address, r.lvdt_kind, r.lvdt.type},
      {"modbus.registers.setpoint_address", "the setpoint's holding registers", true, r.setpoint_address,
       RegisterKind::kHolding, r.setpoint.type},
      {"modbus.registers.current_feedback_address", "the current feedback's registers", r.has_current_feedback,
       r.current_feedback_address, r.current_feedback_kind, r.current_feedback.type},
      {"modbus.registers.demand_address", "the demand's registers", r.has_demand, r.demand_address, r.demand_kind,
       r.demand.type},
      {"modbus.registers.demand_counter_address", "the demand counter's register", r.has_demand_counter(),
       r.demand_counter_address, r.demand_kind, RegisterType::kUint16},
      {"modbus.registers.load_cell_address", "the load cell's registers", r.has_load_cell, r.load_cell_address,
       r.load_cell_kind, r.load_cell.type},
  }};
  const auto overlap = [](const Value& a, const Value& b) {
    return a.kind == b.kind && a.address < b.address + static_cast<int>(word_count(b.type)) &&
           b.address < a.address + static_cast<int>(word_count(a.type));
  };
  for (std::size_t i = 1; i < values.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (values[i].present && values[j].present && overlap(values[i], values[j])) {
        in.error(values[i].key, std::string("overlaps ") + values[j].what);
      }
    }
  }
}

// Checks that need more than one section, and the physics of the whole.
void cross_check(TomlReader& in, const ControllerConfig& c) {
  const auto& law = c.law;
  if (!(c.rate >= 10.0 && c.rate <= 20000.0)) {
    in.error("loop.rate", "must be in 10..20000 Hz, got " + format_value(c.rate));
  }
  for (std::size_t i = 0; i < law.schedule.currents.size(); ++i) {
    if (law.schedule.currents[i] > law.limits.max_current) {
      in.error("schedule.currents[" + std::to_string(i) + "]",
               "must not exceed compensator.max_current (" + format_value(law.limits.max_current) +
                   " A): the driver cannot reach it");
    }
  }
  const auto& s = c.safety;
  if (s.fail_safe_current < law.limits.min_current || s.fail_safe_current > law.limits.max_current) {
    in.error("safety.fail_safe_current", "must lie within compensator.min_current..max_current");
  }
  if (law.schedule.thresholds.back() >= s.displacement_max ||
      -law.schedule.thresholds.back() <= s.displacement_min) {
    in.warning("safety.displacement_max",
               "the range does not reach past the last schedule threshold: the top level is never "
               "used");
  }
  if (c.backends.lvdt == DeviceBackend::kMock &&
      (c.simulation.amplitude > s.displacement_max || -c.simulation.amplitude < s.displacement_min)) {
    in.error("simulation.amplitude", "must stay within safety.displacement_min..max, or the "
                                     "simulated rig trips the supervisor every stroke");
  }
  // The writer drains once per flush period; the ring must hold two passes' worth. A decimation
  // below 1 is already an error, and would make the count infinite.
  const double per_pass = c.rate * c.telemetry.flush_period / c.telemetry.decimation;
  if (c.telemetry.enabled() && c.telemetry.decimation >= 1 && std::isfinite(per_pass) &&
      c.telemetry.ring_size < 2.0 * per_pass) {
    in.warning("telemetry.ring_size", "holds less than two flush periods of records (" +
                                          std::to_string(static_cast<long>(per_pass)) +
                                          " each): expect dropped records");
  }
  if (c.backends.demand == DeviceBackend::kMock && c.backends.lvdt != DeviceBackend::kMock) {
    in.error("backends.demand", "\"mock\" asks for simulation.demand_damping times the mock LVDT's velocity: "
                                "it needs backends.lvdt = \"mock\"");
  }
  if (c.backends.load_cell == DeviceBackend::kMock && c.backends.lvdt != DeviceBackend::kMock) {
    in.error("backends.load_cell", "\"mock\" measures the simulated rig's force: it needs backends.lvdt = \"mock\"");
  }
  if (c.backends.uses(DeviceBackend::kModbus)) check_register_overlaps(in, c.modbus.registers);
}

void validate_all(TomlReader& in, ControllerConfig& c) {
  c.law.observer.sample_period = 1.0 / c.rate;
  report(in, c.modbus.validate(), "modbus");
  report(in, c.can.validate(), "can");
  report(in, c.gpio.validate(), "gpio");
  report(in, c.simulation.validate(), "simulation");
  const ValidationReport safety = c.safety.validate();
  for (const auto& p : safety.issues()) in.error(safety_key(p.field), p.message);
  report(in, c.realtime.validate(), "realtime");
  report(in, c.telemetry.validate(), "telemetry");
  const ValidationReport law_report = validate(c.law);
  for (const auto& issue : law_report.issues()) {
    // The sample period is 1 / loop.rate: a bad rate is reported once, as itself.
    if (issue.field == "observer.sample_period" && !(c.rate >= 10.0 && c.rate <= 20000.0)) continue;
    if (issue.severity == ValidationIssue::Severity::kError) {
      in.error(file_key(issue.field), issue.message);
    } else {
      in.warning(file_key(issue.field), issue.message);
    }
  }
  if (c.law.limits.max_iterations < 1) {
    in.error("compensator.max_iterations", "must be >= 1, got " + std::to_string(c.law.limits.max_iterations));
  }
  cross_check(in, c);
}

}  // namespace

LoadedConfig load_config_text(std::string_view text, const std::string& file_name) {
  LoadedConfig out;
  const std::optional<toml::table> root = parse_config_text(text, file_name, out.errors);
  if (!root) return out;
  ConfigMessages messages;
  TomlReader in(*root, file_name, messages);
  read_all(in, out.config);
  in.report_unknown_keys();
  validate_all(in, out.config);
  file_messages(messages, out.errors, out.warnings);
  out.keys = in.keys();
  out.defaulted = in.defaulted();
  return out;
}

LoadedConfig revalidate(const ControllerConfig& config, const std::string& source) {
  LoadedConfig out;
  out.config = config;
  const toml::table empty;
  ConfigMessages messages;
  TomlReader in(empty, source, messages);
  validate_all(in, out.config);
  for (auto& m : messages) (m.warning ? out.warnings : out.errors).push_back(std::move(m));
  return out;
}

namespace {

// A file that leaves out a back end (an empty or truncated one among them) would run the mock,
// drive nothing and report healthy: each must be named, the demand's in force mode too.
LoadedConfig with_backends_named(LoadedConfig loaded, const std::string& file_name) {
  std::vector<std::string_view> required{"backends.lvdt", "backends.driver", "backends.lines"};
  if (loaded.config.law.mode == control::ControlMode::kForce) required.push_back("backends.demand");
  for (const std::string_view key : required) {
    if (std::find(loaded.defaulted.begin(), loaded.defaulted.end(), key) == loaded.defaulted.end()) continue;
    loaded.errors.push_back({.file = file_name,
                             .line = 0,
                             .key = std::string(key),
                             .message = std::string("must be named (") +
                                        (key == "backends.lines" ? "mock | gpio" : "mock | modbus | can") +
                                        "): a file without it would run the simulation and drive nothing"});
  }
  return loaded;
}

}  // namespace

LoadedConfig load_config_file(const std::string& path, std::string* text_out) {
  LoadedConfig out;
  const std::optional<std::string> text = read_config_file(path, out.errors);
  if (text && text_out != nullptr) *text_out = *text;
  return text ? with_backends_named(load_config_text(*text, path), path) : out;
}

std::string_view default_config_text() { return kDefaultConfigText; }

LoadedConfig load_default_config() {
  const std::string name = "<embedded etc/mrd/mrd.toml>";
  return with_backends_named(load_config_text(default_config_text(), name), name);
}

}  // namespace mrd::config
