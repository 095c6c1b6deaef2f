#include "firmware/config_reload.hpp"

#include "config/config_loader.hpp"

namespace mrd::firmware {

ConfigReload::Outcome ConfigReload::check() const {
  constexpr const char* kStays = "the running config stays";
  if (path_.empty()) {
    return {telemetry::Priority::kNotice,
            std::string("SIGHUP: the embedded config runs (no --config): nothing to re-read, ") + kStays};
  }
  std::string text;
  const config::LoadedConfig loaded = config::load_config_file(path_, &text);
  if (!loaded.ok()) {
    std::string report = loaded.report();
    while (report.ends_with('\n')) report.pop_back();
    return {telemetry::Priority::kErr, "SIGHUP: " + path_ + " is not valid (" + std::to_string(loaded.errors.size()) +
                                         " error(s)), " + kStays + ":\n" + report};
  }
  if (text == running_text_) {
    return {telemetry::Priority::kNotice, "SIGHUP: " + path_ + " is valid and unchanged, " + kStays};
  }
  return {telemetry::Priority::kWarning,
          "SIGHUP: " + path_ + " is valid and differs from the running config; it takes effect at the next start "
          "(systemctl restart mrd-controller: SAFE, then a fresh start), " + kStays};
}

}  // namespace mrd::firmware
