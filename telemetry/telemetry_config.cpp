#include "telemetry/telemetry_config.hpp"

#include <cmath>
#include <filesystem>

namespace mrd::telemetry {

std::string TelemetryConfig::resolved_path() const {
  return (std::filesystem::path(directory) / path).lexically_normal().string();
}

namespace {

// The file `path` names once every symbolic link in it is followed, or an error.
std::filesystem::path real_path(const std::filesystem::path& path, std::error_code& error) {
  return std::filesystem::weakly_canonical(std::filesystem::absolute(path, error), error);
}

}  // namespace

ValidationReport TelemetryConfig::validate() const {
  ValidationReport r;
  r.check(!directory.empty(), "directory", "must name a directory (\".\" for the working one)");
  if (enabled() && !directory.empty()) {
    std::error_code error;
    const auto base = real_path(directory, error);
    const auto target = error ? std::filesystem::path{} : real_path(resolved_path(), error);
    const auto inside = target.lexically_relative(base);
    const bool escapes = error || inside.empty() || inside == "." || *inside.begin() == "..";
    r.check(!escapes, "path",
            "'" + path + "' resolves to " + (error ? error.message() : target.string()) +
                ", not a file below telemetry.directory '" + directory + "'");
  }
  r.check(decimation >= 1, "decimation", "must be >= 1, got " + std::to_string(decimation));
  r.check(ring_size >= 16 && ring_size <= (1 << 22), "ring_size",
          "must be in 16..4194304 records, got " + std::to_string(ring_size));
  r.check(max_bytes == 0 || max_bytes >= 4096, "max_bytes",
          "must be 0 (no cap) or at least 4096 bytes, got " + std::to_string(max_bytes));
  r.check(std::isfinite(flush_period) && flush_period > 0.0 && flush_period <= 10.0, "flush_period",
          "must be in (0, 10] s");
  return r;
}

}  // namespace mrd::telemetry
