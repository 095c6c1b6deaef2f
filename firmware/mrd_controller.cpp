// mrd-controller: the MR damper controller. Reads a TOML config (or the embedded default, which
// runs on the mock HAL with its LVDT on a sine), runs the fixed-rate loop on a real-time thread, and
// prints loop statistics and supervisor transitions at exit and on SIGUSR1.
#include <CLI/CLI.hpp>
#include <filesystem>

#include <cstdio>
#include <string>

#include "common/cli/command_line.hpp"
#include "config/config_loader.hpp"
#include "firmware/config_reload.hpp"
#include "firmware/controller.hpp"
#include "firmware/probe.hpp"

namespace {

mrd::runtime::ProcessSignals g_signals;

int print_report(const mrd::config::LoadedConfig& loaded, const std::string& name) {
  std::fputs(loaded.report().c_str(), loaded.ok() ? stdout : stderr);
  if (!loaded.ok()) {
    std::fprintf(stderr, "%s: %zu error(s)\n", name.c_str(), loaded.errors.size());
    return mrd::cli::kUsage;
  }
  return mrd::cli::kOk;
}

// Modbus TCP to another host needs the network up before the service starts; the unit does not
// order itself after network-online.target, since CAN and RTU boxes must not wait for it.
void note_network(const mrd::config::ControllerConfig& config) {
  if (!config.backends.uses(mrd::config::DeviceBackend::kModbus) ||
      config.modbus.transport != mrd::hal::modbus::Transport::kTcp) {
    return;
  }
  const std::string& host = config.modbus.tcp.host;
  if (host == "localhost" || host.starts_with("127.") || host == "::1") return;
  std::printf("note: Modbus TCP to %s needs the network: order the service after network-online.target "
              "(systemctl edit mrd-controller.service; docs/DEPLOY.md, \"The network\")\n",
              host.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"mrd-controller: real-time MR damper controller (default: the mock HAL)"};
  mrd::cli::set_up(app, "mrd-controller");
  app.footer(mrd::cli::exit_code_footer() +
             " 4: the run ended in SAFE through a fault, not through the stop (the trigger and any link "
             "down printed last).");
  std::string config_path;
  std::string check_path;
  std::string telemetry_path;
  double rate = 0.0;
  bool print_default = false;
  bool probe = false;
  mrd::firmware::RunOptions options;
  app.add_option("--config", config_path, "TOML config file (default: the embedded config, "
                                          "also installed as etc/mrd/mrd.toml)");
  app.add_option("--check-config", check_path, "validate FILE, print every problem, exit 0 or 1");
  app.add_option("--duration", options.duration_s, "run this many seconds (0: until SIGTERM or SIGINT; SIGHUP re-checks the config file)")
      ->check(mrd::cli::finite_in(0.0, 1e7))->capture_default_str();
  app.add_option("--telemetry", telemetry_path, "write telemetry CSV to exactly this file (overrides telemetry.path, telemetry.directory with its directory, and telemetry.per_run)");
  app.add_option("--rate", rate, "control rate [Hz] (overrides loop.rate)")->check(mrd::cli::finite_in(10.0, 20000.0));
  app.add_flag("--bench", options.bench,
               "loop benchmark: mock HAL and its sine whatever the config says, no telemetry, "
               "latency histograms printed");
  app.add_flag("--print-default-config", print_default, "print the embedded default config and exit");
  app.add_flag("--probe", probe,
               "commissioning: open the configured buses with the driver held off (enable low, no setpoint "
               "written), print decoded LVDT and current readings for 1 s, exit 0 (ok), 2 (readings "
               "wrong, each problem printed) or 3 (a bus cannot start)");
  if (const auto status = mrd::cli::parse(app, argc, argv)) return *status;

  if (print_default) {
    std::fwrite(mrd::config::default_config_text().data(), 1,
                mrd::config::default_config_text().size(), stdout);
    return mrd::cli::kOk;
  }
  if (!check_path.empty()) {
    const auto loaded = mrd::config::load_config_file(check_path);
    const int rc = print_report(loaded, check_path);
    if (rc == 0) {
      note_network(loaded.config);
      std::printf("%s: ok\n", check_path.c_str());
    }
    return rc;
  }

  std::string config_text;  // what SIGHUP compares the file with
  auto loaded = config_path.empty() ? mrd::config::load_default_config()
                                    : mrd::config::load_config_file(config_path, &config_text);
  if (print_report(loaded, config_path.empty() ? "embedded config" : config_path) != 0) return mrd::cli::kUsage;

  auto config = loaded.config;
  if (rate > 0.0) config.rate = rate;
  if (!telemetry_path.empty()) {
    // The operator named the file on the command line, and so its directory: the config's
    // telemetry.directory confines the paths a config file may give, not this one.
    const std::filesystem::path file(telemetry_path);
    config.telemetry.directory = file.has_parent_path() ? file.parent_path().string() : ".";
    config.telemetry.path = file.filename().string();
    config.telemetry.per_run = false;  // exactly the file named, as before
  }
  if (options.bench) {
    config.backends = {};  // all mock
    config.telemetry.path.clear();
  }
  const auto checked = mrd::config::revalidate(config, "command line");
  if (print_report(checked, "command line") != 0) return mrd::cli::kUsage;
  if (probe) return mrd::firmware::run_probe(checked.config, {}, stdout);

  // The loop, bus and telemetry threads inherit a mask without the signals, so only the main
  // thread takes them; it polls the flags the handlers set.
  const mrd::firmware::ConfigReload reload(config_path, config_text);
  options.reload = &reload;
  const sigset_t mask = mrd::runtime::install_process_signals(g_signals);
  return mrd::firmware::run_controller(checked.config, options, g_signals, stdout, &mask);
}
