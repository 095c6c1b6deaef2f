#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "config/config_loader.hpp"
#include "record/run_read_options.hpp"

namespace mrd::tools {

// The command-line options every tool that reads recorded runs shares: --columns, --current,
// --current-from-name, --sample-rate and --amps-per-volt, and the --config it reads them with.
class RunOptionsCli {
 public:
  void add_to(CLI::App& app);

  // The controller's config (--config, or the embedded one), its problems printed to stderr
  // with the warnings; nullopt when it has errors.
  [[nodiscard]] std::optional<config::LoadedConfig> load_config() const;
  // How to read the runs, with the config's CAN ids for logs. Throws InputError (a bad mapping).
  [[nodiscard]] record::RunReadOptions read_options(const config::LoadedConfig& config) const;
  [[nodiscard]] std::optional<double> amps_per_volt() const;
  [[nodiscard]] const std::string& config_path() const { return config_path_; }

 private:
  std::string columns_;
  std::string config_path_;
  double current_ = 0.0;
  double sample_rate_ = 0.0;
  double amps_per_volt_ = 0.0;
  bool current_from_name_ = false;
  CLI::Option* current_option_ = nullptr;
  CLI::Option* rate_option_ = nullptr;
  CLI::Option* gain_option_ = nullptr;
};

}  // namespace mrd::tools
