#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "control/supervisor.hpp"
#include "hal/clock.hpp"
#include "telemetry/telemetry_alarm.hpp"

namespace mrd::telemetry {

// The STATUS= line systemctl status shows: state, rate, wake-up p99 and overruns so far.
struct ServiceStatus {
  control::SupervisorState state = control::SupervisorState::kInit;
  bool latched = false;            // SAFE until an operator's SIGUSR2
  double rate = 0.0;               // [Hz]
  std::uint64_t cycles = 0;
  std::uint64_t overruns = 0;
  std::uint64_t wake_p99_ns = 0;   // since start
  bool bus_stalled = false;        // a bus I/O thread is hung: the watchdog is not fed
  TelemetryLosses telemetry;
};
// "RUN, 1000 Hz, wake-up p99 42.1 us, overruns 0, cycles 120000"; a latched SAFE reads
// "SAFE latched (clear: SIGUSR2), 1000 Hz, ...", so `systemctl status` says what to do; lost
// telemetry adds "; telemetry: 3 records dropped (the ring was full), ...".
[[nodiscard]] std::string format_status(const ServiceStatus& s);

// systemd's service protocol through libsystemd's sd_notify (Type=notify, WatchdogSec=). Every
// call is a no-op outside systemd (no NOTIFY_SOCKET). Runs on a non-real-time thread only:
// sd_notify is a socket write. Time comes in as an argument, so tests script it.
class ServiceNotifier {
 public:
  // Reads the watchdog interval systemd passed (WATCHDOG_USEC for this pid), once.
  explicit ServiceNotifier(std::chrono::nanoseconds status_period = std::chrono::seconds(1));

  // READY=1 with the first STATUS=, once the buses and the real-time set-up are done.
  void ready(const ServiceStatus& status, hal::Timestamp now);
  // STOPPING=1 with a last STATUS= when the run ends.
  void stopping(const std::string& why);
  // Periodically: WATCHDOG=1 when at least half the interval has passed since the last one,
  // the loop's cycle count advanced since then and no bus thread is stalled (a stalled loop or
  // bus thread starves the watchdog and systemd restarts the service); STATUS= every status
  // period.
  void tick(hal::Timestamp now, const ServiceStatus& status);

  [[nodiscard]] std::chrono::nanoseconds watchdog_interval() const { return watchdog_; }
  [[nodiscard]] std::uint64_t watchdog_kicks() const { return kicks_; }
  [[nodiscard]] std::uint64_t withheld_kicks() const { return withheld_; }

 private:
  void send(const std::string& message);

  std::chrono::nanoseconds status_period_;
  std::chrono::nanoseconds watchdog_{0};  // 0: no watchdog asked for
  hal::Timestamp last_kick_{};
  hal::Timestamp last_status_{};
  std::uint64_t cycles_at_kick_ = 0;
  std::uint64_t kicks_ = 0;
  std::uint64_t withheld_ = 0;  // kicks due while the cycle count or a bus thread stood still
};

}  // namespace mrd::telemetry
