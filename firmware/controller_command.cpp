#include "firmware/controller_command.hpp"

#include <cstdio>
#include <filesystem>
#include <optional>

#include "common/cli/exit_code.hpp"
#include "config/config_loader.hpp"
#include "firmware/config_reload.hpp"
#include "firmware/probe.hpp"

namespace mrd::firmware {

namespace {

int print_report(const config::LoadedConfig& loaded, const std::string& name) {
  std::fputs(loaded.report().c_str(), loaded.ok() ? stdout : stderr);
  if (!loaded.ok()) {
    std::fprintf(stderr, "%s: %zu error(s)\n", name.c_str(), loaded.errors.size());
    return cli::kUsage;
  }
  return cli::kOk;
}

// Modbus TCP to another host needs the network up before the service starts; the unit does not
// order itself after network-online.target, since CAN and RTU boxes must not wait for it.
void note_network(const config::ControllerConfig& config) {
  if (!config.backends.uses(config::DeviceBackend::kModbus) || config.modbus.transport != hal::modbus::Transport::kTcp) {
    return;
  }
  const std::string& host = config.modbus.tcp.host;
  if (host == "localhost" || host.starts_with("127.") || host == "::1") return;
  std::printf("note: Modbus TCP to %s needs the network: order the service after network-online.target "
              "(systemctl edit mrd-controller.service; docs/DEPLOY.md, \"The network\")\n",
              host.c_str());
}

int check_config(const std::string& path) {
  const auto loaded = config::load_config_file(path);
  const int rc = print_report(loaded, path);
  if (rc == cli::kOk) {
    note_network(loaded.config);
    std::printf("%s: ok\n", path.c_str());
  }
  return rc;
}

void apply_overrides(const ControllerCommand& command, config::ControllerConfig& config) {
  if (command.rate > 0.0) config.rate = command.rate;
  if (!command.telemetry_path.empty()) {
    // The operator named the file on the command line, and so its directory: the config's
    // telemetry.directory confines the paths a config file may give, not this one.
    const std::filesystem::path file(command.telemetry_path);
    config.telemetry.directory = file.has_parent_path() ? file.parent_path().string() : ".";
    config.telemetry.path = file.filename().string();
    config.telemetry.per_run = false;  // exactly the file named, as before
  }
  if (command.options.bench) {
    config.backends = {};  // all mock
    config.telemetry.path.clear();
  }
}

// The config file (or the embedded one) with the command line's overrides, each problem printed;
// nullopt when either is invalid. `text`: the file's text, what SIGHUP compares the file with.
std::optional<config::ControllerConfig> load_config(const ControllerCommand& command, std::string& text) {
  const bool embedded = command.config_path.empty();
  const auto loaded = embedded ? config::load_default_config() : config::load_config_file(command.config_path, &text);
  if (print_report(loaded, embedded ? "embedded config" : command.config_path) != cli::kOk) return std::nullopt;
  config::ControllerConfig config = loaded.config;
  apply_overrides(command, config);
  const auto checked = config::revalidate(config, "command line");
  if (print_report(checked, "command line") != cli::kOk) return std::nullopt;
  return checked.config;
}

}  // namespace

int run_command(const ControllerCommand& command, runtime::ProcessSignals& signals) {
  if (command.print_default) {
    const std::string_view text = config::default_config_text();
    std::fwrite(text.data(), 1, text.size(), stdout);
    return cli::kOk;
  }
  if (!command.check_path.empty()) return check_config(command.check_path);
  std::string config_text;
  const auto config = load_config(command, config_text);
  if (!config) return cli::kUsage;
  if (command.probe) return run_probe(*config, {}, stdout);

  const ConfigReload reload(command.config_path, config_text);
  RunOptions options = command.options;
  options.reload = &reload;
  // The loop, bus and telemetry threads inherit a mask without the signals, so only the main
  // thread takes them; it polls the flags the handlers set.
  const sigset_t mask = runtime::install_process_signals(signals);
  return run_controller(*config, options, signals, stdout, &mask);
}

}  // namespace mrd::firmware
