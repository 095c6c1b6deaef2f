#include "sim/plant/plant_run.hpp"

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/cli/exit_code.hpp"
#include "runtime/loop_report.hpp"
#include "sim/plant/can_node.hpp"
#include "sim/plant/modbus_server.hpp"
#include "sim/plant/run_log.hpp"

namespace mrd::plant {

namespace {

// The buses the plant serves, started; and which one carries the coil current.
struct PlantBuses {
  std::unique_ptr<ModbusServer> modbus;
  std::unique_ptr<CanNode> can;
  bool current_from_can = false;

  [[nodiscard]] bool start(const PlantConfig& config);
  [[nodiscard]] std::vector<hal::IoThread*> io_threads() const {
    std::vector<hal::IoThread*> threads;
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
  // One period's readings onto every bus; `demand`: force mode's outer controller, when it sends one.
  void serve(double t, const RigSample& s, std::optional<double> demand) {
    const SensorReadings readings{.lvdt = s.lvdt, .coil_current = s.reading.coil_current, .demand = demand};
    if (modbus) modbus->publish(readings, s.faults);
    if (can) can->send(t, readings, s.faults);
    // The load cell, when the controller reads one from our buses: the rig's measured force.
    if (modbus) modbus->publish_load_cell(s.reading.measured_force);
    if (can) can->send_load_cell(s.reading.measured_force);
  }
  void stop() {
    if (modbus) modbus->stop();
    if (can) can->stop();
  }
};

bool PlantBuses::start(const PlantConfig& config) {
  if (config.modbus.enabled) {
    modbus = std::make_unique<ModbusServer>(config.controller.modbus, config.listen_host(), config.listen_port(),
                                            config.modbus.rtu_link, config.seed);
    if (const auto started = modbus->start(); !started.ok) {
      std::fprintf(stderr, "mrd-plant: %s\n", started.error.c_str());
      return false;
    }
  }
  if (config.can.enabled) {
    can = std::make_unique<CanNode>(config.controller.can, config.can_interface(), config.can.feedback,
                                    config.can.fault_pull, config.seed);
    if (const auto started = can->start(); !started.ok) {
      std::fprintf(stderr, "mrd-plant: %s\n", started.error.c_str());
      return false;
    }
  }
  // The controller's driver back end when the plant serves it, else whichever bus it serves.
  current_from_can = can && (config.controller.backends.driver == config::DeviceBackend::kCan || !modbus);
  return true;
}

// "name: key=value key=value ...", a line on stdout.
void print_counters(const char* name, std::initializer_list<std::pair<const char*, std::uint64_t>> counters) {
  std::printf("%s:", name);
  for (const auto& [key, value] : counters) std::printf(" %s=%llu", key, static_cast<unsigned long long>(value));
  std::printf("\n");
}

// mrd-plant's run: a method per step of its lifecycle, which run_plant calls in order, and one
// per hook of the real-time skeleton it uses.
class Plant final : public runtime::RealTimeHooks {
 public:
  Plant(const PlantConfig& config, Rig& rig) : config_(config), rig_(rig) {}

  [[nodiscard]] int configure();
  void activate() const;
  void run(runtime::ProcessSignals& signals, const sigset_t* unblock);
  void deactivate();
  [[nodiscard]] int report();

 private:
  void cycle(hal::Timestamp release);
  void ready(const runtime::RtSetupResult& done) override;
  void print_stats() override;

  const PlantConfig& config_;
  Rig& rig_;
  runtime::RtSetupResult rt_;
  RunLog log_;
  PlantBuses buses_;
  std::vector<hal::IoThread*> io_threads_;
  runtime::LoopStatistics stats_;
  std::optional<hal::Timestamp> start_;
  std::optional<double> fault_origin_;  // plant time of fault time 0
};

// Memory locked, the log open, the buses started: kOk, or kIo.
int Plant::configure() {
  runtime::lock_memory(config_.realtime, rt_);
  if (!config_.log.empty()) {
    if (const auto opened = log_.open(config_.log); !opened.ok) {
      std::fprintf(stderr, "mrd-plant: %s\n", opened.error.c_str());
      return cli::kIo;
    }
  }
  if (!buses_.start(config_)) return cli::kIo;
  io_threads_ = buses_.io_threads();
  return cli::kOk;
}

void Plant::activate() const {
  std::printf("mrd-plant: %.0f Hz, profile %s, %s%s%s%s\n", config_.rate,
              std::string(to_string(config_.profile.kind)).c_str(),
              config_.duration > 0.0 ? (std::to_string(config_.duration) + " s").c_str() : "until SIGTERM",
              config_.faults.empty() ? "" : (", " + std::to_string(config_.faults.size()) + " scripted fault(s)").c_str(),
              config_.log.empty() ? "" : ", log ", config_.log.c_str());
  if (buses_.modbus) {
    std::printf("mrd-plant: modbus %s %s\n",
                config_.controller.modbus.transport == hal::modbus::Transport::kTcp ? "tcp" : "rtu",
                buses_.modbus->endpoint().c_str());
  }
  if (buses_.can) std::printf("mrd-plant: can %s\n", buses_.can->interface().c_str());
}

// The rig moved in real time until the duration ends or a stop signal.
void Plant::run(runtime::ProcessSignals& signals, const sigset_t* unblock) {
  const runtime::RealTimeRun run{
      .realtime = config_.realtime,
      .period = std::chrono::nanoseconds{static_cast<std::int64_t>(1e9 / config_.rate + 0.5)},
      .max_cycles = static_cast<std::uint64_t>(config_.duration * config_.rate + 0.5),
      .io_threads = io_threads_};
  runtime::run_real_time(run, signals, unblock, rt_, stats_, [this](hal::Timestamp release) { cycle(release); },
                         *this);
}

void Plant::deactivate() {
  buses_.stop();
  log_.close();
}

// The statistics and the clocks' origins, for joining the log with the controller's telemetry.
int Plant::report() {
  print_stats();
  if (start_) {
    std::printf("plant log: time_s 0 is CLOCK_MONOTONIC %.9f s\n", std::chrono::duration<double>(*start_).count());
  }
  if (fault_origin_) {
    std::printf("plant faults: time 0 is plant log time_s %.6f s (%s)\n", *fault_origin_,
                config_.faults_from == FaultClock::kStart ? "the start" : "the first command");
  } else if (!config_.faults.empty()) {
    std::printf("plant faults: none ran, no command came\n");
  }
  return cli::kOk;
}

void Plant::cycle(hal::Timestamp release) {
  if (!start_) {
    start_ = release;
    log_.write_time_origin(std::chrono::duration<double>(release).count());
  }
  const double t = std::chrono::duration<double>(release - *start_).count();
  if (!fault_origin_ && (config_.faults_from == FaultClock::kStart || buses_.commanded_yet())) fault_origin_ = t;
  const RigSample& s = rig_.step(
      {.t = t, .fault_t = fault_origin_ ? t - *fault_origin_ : -1.0, .commanded = buses_.commanded_current()});
  // Force mode's outer controller: c v, with the sign of the motion the damper resists.
  buses_.serve(t, s,
               config_.sends_demand() ? std::optional(config_.demand_damping * s.reading.sensor_velocity) : std::nullopt);
  log_.write(s);
}

void Plant::ready(const runtime::RtSetupResult& done) {
  std::printf("mrd-plant: %s\n", runtime::describe_rt_setup(config_.realtime, done, io_threads_.size()).c_str());
  for (const auto& w : done.warnings) std::fprintf(stderr, "mrd-plant: warning: %s\n", w.c_str());
  std::printf("mrd-plant: ready\n");
  std::fflush(stdout);
}

void Plant::print_stats() {
  std::printf("--- mrd-plant statistics ---\n%s", runtime::format_loop_statistics(stats_).c_str());
  if (buses_.modbus) {
    const auto c = buses_.modbus->counters();
    print_counters("modbus server", {{"connections", c.connections}, {"requests", c.requests}, {"answered", c.answered},
                                     {"unanswered", c.unanswered}, {"exceptions", c.exceptions},
                                     {"setpoints", c.setpoints}, {"restarts", c.restarts}});
  }
  if (buses_.can) {
    const auto c = buses_.can->counters();
    print_counters("can node", {{"lvdt_sent", c.lvdt_sent}, {"lvdt_lost", c.lvdt_lost}, {"feedback_sent", c.feedback_sent},
                                {"error_frames", c.error_frames}, {"commands", c.commands},
                                {"bad_commands", c.bad_commands}, {"tx_errors", c.tx_errors}});
  }
  if (!config_.log.empty()) {
    std::printf("plant log: %llu rows -> %s\n", static_cast<unsigned long long>(log_.rows()), config_.log.c_str());
  }
  std::fflush(stdout);
}

}  // namespace

int run_plant(const PlantConfig& config, Rig& rig, runtime::ProcessSignals& signals, const sigset_t* unblock) {
  Plant plant(config, rig);
  if (const int status = plant.configure(); status != cli::kOk) return status;
  plant.activate();
  plant.run(signals, unblock);
  plant.deactivate();
  return plant.report();
}

}  // namespace mrd::plant
