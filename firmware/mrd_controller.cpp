// mrd-controller: the MR damper controller. Reads a TOML config (or the embedded default, which
// runs on the mock HAL with its LVDT on a sine), runs the fixed-rate loop on a real-time thread, and
// prints loop statistics and supervisor transitions at exit and on SIGUSR1.
#include <CLI/CLI.hpp>

#include "common/cli/command_line.hpp"
#include "firmware/controller_command.hpp"

namespace {

mrd::runtime::ProcessSignals g_signals;

void add_options(CLI::App& app, mrd::firmware::ControllerCommand& c) {
  app.add_option("--config", c.config_path, "TOML config file (default: the embedded config, "
                                            "also installed as etc/mrd/mrd.toml)");
  app.add_option("--check-config", c.check_path, "validate FILE, print every problem, exit 0 or 1");
  app.add_option("--duration", c.options.duration_s, "run this many seconds (0: until SIGTERM or SIGINT; SIGHUP re-checks the config file)")
      ->check(mrd::cli::finite_in(0.0, 1e7))->capture_default_str();
  app.add_option("--telemetry", c.telemetry_path, "write telemetry CSV to exactly this file (overrides telemetry.path, telemetry.directory with its directory, and telemetry.per_run)");
  app.add_option("--rate", c.rate, "control rate [Hz] (overrides loop.rate)")->check(mrd::cli::finite_in(10.0, 20000.0));
  app.add_flag("--bench", c.options.bench,
               "loop benchmark: mock HAL and its sine whatever the config says, no telemetry, "
               "latency histograms printed");
  app.add_flag("--print-default-config", c.print_default, "print the embedded default config and exit");
  app.add_flag("--probe", c.probe,
               "commissioning: open the configured buses with the driver held off (enable low, no setpoint "
               "written), print decoded LVDT and current readings for 1 s, exit 0 (ok), 2 (readings "
               "wrong, each problem printed) or 3 (a bus cannot start)");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"mrd-controller: real-time MR damper controller (default: the mock HAL)"};
  mrd::cli::set_up(app, "mrd-controller");
  app.footer(mrd::cli::exit_code_footer() +
             " 4: the run ended in SAFE through a fault, not through the stop (the trigger and any link "
             "down printed last).");
  mrd::firmware::ControllerCommand command;
  add_options(app, command);
  if (const auto status = mrd::cli::parse(app, argc, argv)) return *status;
  return mrd::firmware::run_command(command, g_signals);
}
