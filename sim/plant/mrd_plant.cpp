// mrd-plant: the simulated test rig as its own process. It moves a simulated MR damper along a
// displacement profile in real time, serves the LVDT and takes the coil current over Modbus
// (TCP, or RTU on a pty) and/or CAN exactly as the controller's config lays them out, injects
// the faults its config scripts, and logs the run as a recorded-run CSV.
#include <CLI/CLI.hpp>

#include <chrono>
#include <optional>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "common/cli/command_line.hpp"
#include "runtime/loop_report.hpp"
#include "runtime/rt_main.hpp"
#include "sim/plant/can_node.hpp"
#include "sim/plant/modbus_server.hpp"
#include "sim/plant/plant_config.hpp"
#include "sim/plant/rig.hpp"
#include "sim/plant/run_log.hpp"
#include "record/csv.hpp"

namespace {

mrd::runtime::ProcessSignals g_signals;

void print_summary(std::FILE* out, const mrd::runtime::LoopStatistics& stats,
                   const mrd::plant::ModbusServer* modbus, const mrd::plant::CanNode* can,
                   const mrd::plant::RunLog& log, const std::string& log_path) {
  std::fprintf(out, "--- mrd-plant statistics ---\n%s",
               mrd::runtime::format_loop_statistics(stats).c_str());
  if (modbus != nullptr) {
    const auto c = modbus->counters();
    std::fprintf(out,
                 "modbus server: connections=%llu requests=%llu answered=%llu unanswered=%llu "
                 "exceptions=%llu setpoints=%llu restarts=%llu\n",
                 static_cast<unsigned long long>(c.connections), static_cast<unsigned long long>(c.requests),
                 static_cast<unsigned long long>(c.answered), static_cast<unsigned long long>(c.unanswered),
                 static_cast<unsigned long long>(c.exceptions), static_cast<unsigned long long>(c.setpoints),
                 static_cast<unsigned long long>(c.restarts));
  }
  if (can != nullptr) {
    const auto c = can->counters();
    std::fprintf(out,
                 "can node: lvdt_sent=%llu lvdt_lost=%llu feedback_sent=%llu error_frames=%llu "
                 "commands=%llu bad_commands=%llu tx_errors=%llu\n",
                 static_cast<unsigned long long>(c.lvdt_sent), static_cast<unsigned long long>(c.lvdt_lost),
                 static_cast<unsigned long long>(c.feedback_sent),
                 static_cast<unsigned long long>(c.error_frames), static_cast<unsigned long long>(c.commands),
                 static_cast<unsigned long long>(c.bad_commands), static_cast<unsigned long long>(c.tx_errors));
  }
  if (!log_path.empty()) {
    std::fprintf(out, "plant log: %llu rows -> %s\n", static_cast<unsigned long long>(log.rows()),
                 log_path.c_str());
  }
  std::fflush(out);
}

// The command line's overrides of the plant config.
struct Overrides {
  double duration = -1.0;
  int port = -2;
  std::string log_path;
  bool no_log = false;

  void apply(mrd::plant::PlantConfig& config) const {
    if (duration >= 0.0) config.duration = duration;
    if (port >= 0) config.modbus.port = port;
    if (!log_path.empty()) config.log = log_path;
    if (no_log) config.log.clear();
  }
};

std::optional<mrd::plant::PlantConfig> load_config(const std::string& path, const Overrides& overrides) {
  if (path.empty()) {
    std::fprintf(stderr, "mrd-plant: --config FILE is required (etc/mrd/plant.toml lists every key)\n");
    return std::nullopt;
  }
  auto loaded = mrd::plant::load_plant_config_file(path);
  std::fputs(loaded.report().c_str(), loaded.ok() ? stdout : stderr);
  if (!loaded.ok()) {
    std::fprintf(stderr, "%s: %zu error(s)\n", path.c_str(), loaded.errors.size());
    return std::nullopt;
  }
  mrd::plant::PlantConfig config = loaded.config;
  overrides.apply(config);
  return config;
}

// The buses the plant serves, started; and which one carries the coil current.
struct PlantBuses {
  std::unique_ptr<mrd::plant::ModbusServer> modbus;
  std::unique_ptr<mrd::plant::CanNode> can;
  bool current_from_can = false;

  [[nodiscard]] std::vector<mrd::hal::IoThread*> io_threads() const {
    std::vector<mrd::hal::IoThread*> threads;
    if (modbus) threads.push_back(&modbus->io_thread());
    if (can) threads.push_back(&can->io_thread());
    return threads;
  }
  [[nodiscard]] bool commanded_yet() const {
    return (can && can->counters().commands > 0) || (modbus && modbus->counters().setpoints > 0);
  }
  [[nodiscard]] double commanded_current() const {
    if (current_from_can) return can->enabled() ? can->setpoint() : 0.0;
    return modbus ? modbus->setpoint() : 0.0;
  }
  void stop() {
    if (modbus) modbus->stop();
    if (can) can->stop();
  }
};

bool start_buses(const mrd::plant::PlantConfig& config, PlantBuses& buses) {
  if (config.modbus.enabled) {
    buses.modbus = std::make_unique<mrd::plant::ModbusServer>(config.controller.modbus, config.listen_host(),
                                                              config.listen_port(), config.modbus.rtu_link,
                                                              config.seed);
    if (const auto started = buses.modbus->start(); !started.ok) {
      std::fprintf(stderr, "mrd-plant: %s\n", started.error.c_str());
      return false;
    }
  }
  if (config.can.enabled) {
    buses.can = std::make_unique<mrd::plant::CanNode>(config.controller.can, config.can_interface(),
                                                      config.can.feedback, config.can.fault_pull, config.seed);
    if (const auto started = buses.can->start(); !started.ok) {
      std::fprintf(stderr, "mrd-plant: %s\n", started.error.c_str());
      return false;
    }
  }
  // The controller's driver back end when the plant serves it, else whichever bus it serves.
  buses.current_from_can =
      buses.can && (config.controller.backends.driver == mrd::config::DeviceBackend::kCan || !buses.modbus);
  return true;
}

void print_banner(const mrd::plant::PlantConfig& config, const PlantBuses& buses) {
  std::printf("mrd-plant: %.0f Hz, profile %s, %s%s%s%s\n", config.rate,
              std::string(to_string(config.profile.kind)).c_str(),
              config.duration > 0.0 ? (std::to_string(config.duration) + " s").c_str() : "until SIGTERM",
              config.faults.empty() ? "" : (", " + std::to_string(config.faults.size()) + " scripted fault(s)").c_str(),
              config.log.empty() ? "" : ", log ", config.log.c_str());
  if (buses.modbus) {
    std::printf("mrd-plant: modbus %s %s\n",
                config.controller.modbus.transport == mrd::hal::modbus::Transport::kTcp ? "tcp" : "rtu",
                buses.modbus->endpoint().c_str());
  }
  if (buses.can) std::printf("mrd-plant: can %s\n", buses.can->interface().c_str());
}

// Moves the rig in real time until the duration ends or a stop signal; prints the summary.
int run_plant(const mrd::plant::PlantConfig& config, mrd::plant::Rig& rig) {
  // Before the bus threads start, so they inherit a mask without the signals.
  const sigset_t signal_mask = mrd::runtime::install_process_signals(g_signals);
  mrd::runtime::RtSetupResult rt;
  mrd::runtime::lock_memory(config.realtime, rt);
  mrd::plant::RunLog log;
  if (!config.log.empty()) {
    if (const auto opened = log.open(config.log); !opened.ok) {
      std::fprintf(stderr, "mrd-plant: %s\n", opened.error.c_str());
      return mrd::cli::kIo;
    }
  }
  PlantBuses buses;
  if (!start_buses(config, buses)) return mrd::cli::kIo;
  print_banner(config, buses);
  const std::vector<mrd::hal::IoThread*> io_threads = buses.io_threads();

  std::optional<mrd::hal::Timestamp> start;
  std::optional<double> fault_origin;  // plant time of fault time 0
  const auto cycle = [&](mrd::hal::Timestamp release) {
    if (!start) {
      start = release;
      log.write_time_origin(std::chrono::duration<double>(release).count());
    }
    const double t = std::chrono::duration<double>(release - *start).count();
    if (!fault_origin && (config.faults_from == mrd::plant::FaultClock::kStart || buses.commanded_yet())) {
      fault_origin = t;
    }
    const auto& s = rig.step(t, fault_origin ? t - *fault_origin : -1.0, buses.commanded_current());
    // Force mode's outer controller: c v, with the sign of the motion the damper resists.
    const std::optional<double> demand =
        config.sends_demand() ? std::optional(config.demand_damping * s.reading.sensor_velocity) : std::nullopt;
    if (buses.modbus) buses.modbus->publish(s.lvdt, s.reading.coil_current, demand, s.faults);
    if (buses.can) buses.can->send(t, s.lvdt, s.reading.coil_current, demand, s.faults);
    // The load cell, when the controller reads one from our buses: the rig's measured force.
    if (buses.modbus) buses.modbus->publish_load_cell(s.reading.measured_force);
    if (buses.can) buses.can->send_load_cell(s.reading.measured_force);
    log.write(s);
  };
  mrd::runtime::LoopStatistics stats;
  const mrd::runtime::RealTimeRun run{
      .realtime = config.realtime,
      .period = std::chrono::nanoseconds{static_cast<std::int64_t>(1e9 / config.rate + 0.5)},
      .max_cycles = static_cast<std::uint64_t>(config.duration * config.rate + 0.5),
      .io_threads = io_threads};
  const mrd::runtime::RealTimeHooks hooks{
      .finish = nullptr,
      .ready =
          [&](const mrd::runtime::RtSetupResult& done) {
            std::printf("mrd-plant: %s\n",
                        mrd::runtime::describe_rt_setup(config.realtime, done, io_threads.size()).c_str());
            for (const auto& w : done.warnings) std::fprintf(stderr, "mrd-plant: warning: %s\n", w.c_str());
            std::printf("mrd-plant: ready\n");
            std::fflush(stdout);
          },
      .print_stats = [&] { print_summary(stdout, stats, buses.modbus.get(), buses.can.get(), log, config.log); }};
  mrd::runtime::run_real_time(run, g_signals, &signal_mask, rt, stats, cycle, hooks);

  buses.stop();
  log.close();
  print_summary(stdout, stats, buses.modbus.get(), buses.can.get(), log, config.log);
  if (start) {
    std::printf("plant log: time_s 0 is CLOCK_MONOTONIC %.9f s\n", std::chrono::duration<double>(*start).count());
  }
  if (fault_origin) {
    std::printf("plant faults: time 0 is plant log time_s %.6f s (%s)\n", *fault_origin,
                config.faults_from == mrd::plant::FaultClock::kStart ? "the start" : "the first command");
  } else if (!config.faults.empty()) {
    std::printf("plant faults: none ran, no command came\n");
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"mrd-plant: the simulated damper rig, serving the controller over Modbus and CAN"};
  mrd::cli::set_up(app, "mrd-plant");
  std::string config_path;
  std::string check_path;
  Overrides overrides;
  app.add_option("--config", config_path, "plant TOML file (etc/mrd/plant.toml lists every key)");
  app.add_option("--check-config", check_path, "validate FILE, print every problem, exit 0 or 1");
  app.add_option("--duration", overrides.duration,
                 "run this many seconds (overrides plant.duration; 0: until SIGTERM)")
      ->check(mrd::cli::finite_in(0.0, 1e7));
  app.add_option("--port", overrides.port, "Modbus TCP port (overrides modbus.port; 0: any free port, printed)")
      ->check(CLI::Range(0, 65535));
  app.add_option("--log", overrides.log_path, "recorded-run CSV (overrides plant.log)");
  app.add_flag("--no-log", overrides.no_log, "write no log");
  if (const auto status = mrd::cli::parse(app, argc, argv)) return *status;

  if (!check_path.empty()) {
    const auto loaded = mrd::plant::load_plant_config_file(check_path);
    std::fputs(loaded.report().c_str(), loaded.ok() ? stdout : stderr);
    if (loaded.ok()) std::printf("%s: ok\n", check_path.c_str());
    return loaded.ok() ? mrd::cli::kOk : mrd::cli::kUsage;
  }
  auto config = load_config(config_path, overrides);
  if (!config) return mrd::cli::kUsage;
  std::unique_ptr<mrd::plant::Rig> rig;
  try {
    auto motion = mrd::plant::make_motion(*config);
    if (config->duration == 0.0) config->duration = mrd::plant::motion_length(motion);
    rig = std::make_unique<mrd::plant::Rig>(*config, std::move(motion));
  } catch (const mrd::record::InputError& e) {
    std::fprintf(stderr, "mrd-plant: profile.file: %s\n", e.what());
    return mrd::cli::kBadInput;
  }
  return run_plant(*config, *rig);
}
