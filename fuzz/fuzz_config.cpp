// libFuzzer target: the TOML config loader and validator (firmware/config_loader). Any text.
// It must never throw: every problem is a message. A config it accepts must also pass the
// validator again on its own (what --check-config and the command-line overrides rely on).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "config/config_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto loaded = mrd::config::load_config_text(text, "fuzz.toml");
  if (loaded.ok() && !mrd::config::revalidate(loaded.config, "fuzz").ok()) std::abort();
  if (!loaded.ok() && loaded.report().empty()) std::abort();
  return 0;
}
