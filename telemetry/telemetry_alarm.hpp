#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

#include "hal/clock.hpp"
#include "telemetry/journal.hpp"

namespace mrd::telemetry {

// What telemetry lost so far: the ring's drops (the writer fell behind) and the records the
// file did not take (telemetry::CsvTelemetryWriter::lost, with the errno of the latest failure).
struct TelemetryLosses {
  std::uint64_t dropped = 0;
  std::uint64_t lost = 0;
  int error = 0;  // 0: none yet

  [[nodiscard]] bool any() const { return dropped > 0 || lost > 0 || error != 0; }
};

// strerror(error), but ETIMEDOUT (the writer's own) reads "the file took nothing within the write
// timeout": a FIFO's reader that stopped draining.
[[nodiscard]] std::string telemetry_error_text(int error);
// "telemetry: 120 records dropped (the ring was full), 501 lost to I/O (No space left on device)";
// empty when nothing was lost.
[[nodiscard]] std::string describe_losses(const TelemetryLosses& l);

struct TelemetryAlarmLine {
  Priority priority;  // an I/O failure is an error, drops a warning
  std::string text;
};

// Telemetry's losses in the journal while the run goes on, without a line per record: a new
// condition (the first drop, the first failure, another errno) at once, further losses at most
// once per `interval`. Time comes in as an argument, so tests script it.
class TelemetryAlarm {
 public:
  explicit TelemetryAlarm(std::chrono::nanoseconds interval = std::chrono::seconds(5)) : interval_(interval) {}

  [[nodiscard]] std::optional<TelemetryAlarmLine> check(const TelemetryLosses& now_losses, hal::Timestamp now);

 private:
  std::chrono::nanoseconds interval_;
  TelemetryLosses reported_;
  std::optional<hal::Timestamp> last_;  // the last line's time
};

}  // namespace mrd::telemetry
