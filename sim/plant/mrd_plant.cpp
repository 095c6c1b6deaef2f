// mrd-plant: the simulated test rig as its own process. It moves a simulated MR damper along a
// displacement profile in real time, serves the LVDT and takes the coil current over Modbus
// (TCP, or RTU on a pty) and/or CAN exactly as the controller's config lays them out, injects
// the faults its config scripts, and logs the run as a recorded-run CSV.
#include <CLI/CLI.hpp>

#include "common/cli/command_line.hpp"
#include "sim/plant/plant_command.hpp"

namespace {

mrd::runtime::ProcessSignals g_signals;

void add_options(CLI::App& app, mrd::plant::PlantCommand& c) {
  app.add_option("--config", c.config_path, "plant TOML file (etc/mrd/plant.toml lists every key)");
  app.add_option("--check-config", c.check_path, "validate FILE, print every problem, exit 0 or 1");
  app.add_option("--duration", c.duration, "run this many seconds (overrides plant.duration; 0: until SIGTERM)")
      ->check(mrd::cli::finite_in(0.0, 1e7));
  app.add_option("--port", c.port, "Modbus TCP port (overrides modbus.port; 0: any free port, printed)")
      ->check(CLI::Range(0, 65535));
  app.add_option("--log", c.log_path, "recorded-run CSV (overrides plant.log)");
  app.add_flag("--no-log", c.no_log, "write no log");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"mrd-plant: the simulated damper rig, serving the controller over Modbus and CAN"};
  mrd::cli::set_up(app, "mrd-plant");
  mrd::plant::PlantCommand command;
  add_options(app, command);
  if (const auto status = mrd::cli::parse(app, argc, argv)) return *status;
  return mrd::plant::run_command(command, g_signals);
}
