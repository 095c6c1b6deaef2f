#include "telemetry/telemetry_alarm.hpp"

#include <cerrno>
#include <cinttypes>
#include <cstdio>
#include <cstring>

namespace mrd::telemetry {

std::string telemetry_error_text(int error) {
  return error == ETIMEDOUT ? "the file took nothing within the write timeout" : std::strerror(error);
}

std::string describe_losses(const TelemetryLosses& l) {
  std::string text;
  char part[160];
  if (l.dropped > 0) {
    std::snprintf(part, sizeof part, "%" PRIu64 " records dropped (the ring was full)", l.dropped);
    text += part;
  }
  if (l.lost > 0 || l.error != 0) {
    std::snprintf(part, sizeof part, "%s%" PRIu64 " lost to I/O (%s)", text.empty() ? "" : ", ", l.lost,
                  l.error != 0 ? telemetry_error_text(l.error).c_str() : "no error");
    text += part;
  }
  return text;
}

std::optional<TelemetryAlarmLine> TelemetryAlarm::check(const TelemetryLosses& l, hal::Timestamp now) {
  const bool grew = l.dropped > reported_.dropped || l.lost > reported_.lost;
  const bool new_condition = (l.dropped > 0 && reported_.dropped == 0) || (l.lost > 0 && reported_.lost == 0) ||
                             l.error != reported_.error;
  if (!new_condition && !(grew && (!last_ || now - *last_ >= interval_))) return std::nullopt;
  reported_ = l;
  last_ = now;
  const bool io = l.lost > 0 || l.error != 0;
  return TelemetryAlarmLine{io ? Priority::kErr : Priority::kWarning, "telemetry: " + describe_losses(l) + " so far"};
}

}  // namespace mrd::telemetry
