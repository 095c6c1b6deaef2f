#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "config/config_message.hpp"
#include "config/controller_config.hpp"

namespace mrd::config {

struct LoadedConfig {
  ControllerConfig config;
  ConfigMessages errors;    // every problem, one per line, file:line: key: message
  ConfigMessages warnings;
  std::vector<std::string> keys;       // every key the loader knows, in file order
  std::vector<std::string> defaulted;  // keys the file left out (their defaults apply)

  [[nodiscard]] bool ok() const { return errors.empty(); }
  [[nodiscard]] std::string report() const;  // errors, then warnings, one per line
};

// Parses and validates. A syntax error stops parsing (one message with line and column);
// otherwise every wrong type, unknown key and out-of-range value is reported at once.
LoadedConfig load_config_text(std::string_view text, const std::string& file_name);
// A file must also name its back ends (backends.lvdt, driver, lines; demand in force mode): an
// empty or truncated file is an error, never a silent run on the mock HAL.
// `text`, if given, receives the file's text as read.
LoadedConfig load_config_file(const std::string& path, std::string* text = nullptr);
// Validates a config changed after loading (command-line overrides); `source` names the change.
LoadedConfig revalidate(const ControllerConfig& config, const std::string& source);

// The config compiled into the binary: etc/mrd/mrd.toml, the simulated rig on the mock HAL,
// its mock back ends named as a file's must be.
std::string_view default_config_text();
LoadedConfig load_default_config();

}  // namespace mrd::config
