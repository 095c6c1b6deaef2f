#include "telemetry/service_notifier.hpp"

#include <systemd/sd-daemon.h>

#include <cinttypes>
#include <cstdio>

namespace mrd::telemetry {

std::string format_status(const ServiceStatus& s) {
  char line[192];
  std::snprintf(line, sizeof line, "%s%s%s, %.0f Hz, wake-up p99 %.1f us, overruns %" PRIu64 ", cycles %" PRIu64,
                std::string(to_string(s.state)).c_str(), s.latched ? " latched (clear: SIGUSR2)" : "",
                s.bus_stalled ? ", bus thread stalled" : "", s.rate, static_cast<double>(s.wake_p99_ns) * 1e-3,
                s.overruns, s.cycles);
  return s.telemetry.any() ? std::string(line) + "; telemetry: " + describe_losses(s.telemetry) : std::string(line);
}

ServiceNotifier::ServiceNotifier(std::chrono::nanoseconds status_period) : status_period_(status_period) {
  std::uint64_t usec = 0;
  if (sd_watchdog_enabled(0, &usec) > 0) watchdog_ = std::chrono::microseconds(usec);
}

void ServiceNotifier::send(const std::string& message) { sd_notify(0, message.c_str()); }

void ServiceNotifier::ready(const ServiceStatus& status, hal::Timestamp now) {
  send("READY=1\nSTATUS=" + format_status(status));
  last_status_ = now;
  last_kick_ = now;
  cycles_at_kick_ = status.cycles;
}

void ServiceNotifier::stopping(const std::string& why) { send("STOPPING=1\nSTATUS=" + why); }

void ServiceNotifier::tick(hal::Timestamp now, const ServiceStatus& status) {
  if (watchdog_.count() > 0 && now - last_kick_ >= watchdog_ / 2) {
    if (status.cycles > cycles_at_kick_ && !status.bus_stalled) {
      send("WATCHDOG=1");
      ++kicks_;
      last_kick_ = now;
      cycles_at_kick_ = status.cycles;
    } else {
      ++withheld_;  // the loop or a bus thread did not move: let systemd's timer run out
    }
  }
  if (now - last_status_ >= status_period_) {
    send("STATUS=" + format_status(status));
    last_status_ = now;
  }
}

}  // namespace mrd::telemetry
