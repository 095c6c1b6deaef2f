#pragma once

#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string_view>

namespace mrd {

// A log's time_s 0 on CLOCK_MONOTONIC, written as a comment line after the CSV header by the
// controller's telemetry and mrd-plant's log, so two logs of one host are joined by time from
// the files alone (mrd-hil-report). Readers skip every line that starts with '#'.
inline constexpr std::string_view kTimeOriginPrefix = "# time_s 0 is CLOCK_MONOTONIC ";

// "# time_s 0 is CLOCK_MONOTONIC 1234.567890123 s\n" into buf (nanoseconds kept); the length,
// as snprintf returns it.
inline int format_time_origin(double monotonic_s, char* buf, std::size_t size) {
  return std::snprintf(buf, size, "%.*s%.9f s\n", static_cast<int>(kTimeOriginPrefix.size()),
                       kTimeOriginPrefix.data(), monotonic_s);
}

// The origin a line written by format_time_origin carries; nullopt for any other line.
inline std::optional<double> parse_time_origin(std::string_view line) {
  if (!line.starts_with(kTimeOriginPrefix)) return std::nullopt;
  line.remove_prefix(kTimeOriginPrefix.size());
  while (!line.empty() && (line.back() == '\r' || line.back() == '\n' || line.back() == ' ')) line.remove_suffix(1);
  if (!line.ends_with(" s")) return std::nullopt;
  line.remove_suffix(2);
  double value = 0.0;
  const auto [end, error] = std::from_chars(line.data(), line.data() + line.size(), value);
  if (error != std::errc{} || end != line.data() + line.size() || !std::isfinite(value) || value < 0.0) {
    return std::nullopt;
  }
  return value;
}

// A comment line in the project's CSV files.
inline bool is_comment_line(std::string_view line) { return line.starts_with('#'); }

}  // namespace mrd
