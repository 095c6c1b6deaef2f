#pragma once

#include <string>

#include "config/config_loader.hpp"

namespace mrd::test {

// True when one of the config's error lines is exactly `line` (file:line: field: message).
inline bool has_error(const config::LoadedConfig& c, const std::string& line) {
  for (const auto& e : c.errors) {
    if (e.to_string() == line) return true;
  }
  return false;
}

}  // namespace mrd::test
