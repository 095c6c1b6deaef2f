#pragma once

#include <string>
#include <vector>

namespace mrd::config {

// One finding about a config file, printed as `file:line: key.path: message` (line 0: the key
// is not in the file, so the default or a parent table is at fault).
struct ConfigMessage {
  std::string file;
  int line = 0;
  std::string key;
  std::string message;
  bool warning = false;

  [[nodiscard]] std::string to_string() const;
};

using ConfigMessages = std::vector<ConfigMessage>;

}  // namespace mrd::config
