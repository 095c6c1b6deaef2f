#pragma once

#include <signal.h>

#include <cstdint>
#include <cstdio>

#include "config/controller_config.hpp"
#include "runtime/rt_main.hpp"

namespace mrd::firmware {

class ConfigReload;

struct RunOptions {
  double duration_s = 0.0;  // 0: until SIGTERM or SIGINT
  bool bench = false;       // also print the latency histograms
  // Supervisor transitions, warnings and the stop, as they happen; null: stderr, with syslog
  // priorities ("<2>...") when stderr is journald's stream (telemetry::Journal).
  std::FILE* log = nullptr;
  // SIGHUP's check of the config file, its answer into the log; null: "nothing to re-read".
  const ConfigReload* reload = nullptr;
};

// mrd-controller's run, in the steps of a lifecycle (ros2_control's): configure (the back ends,
// the telemetry writer and the loop built and started), activate (what runs printed), run (the
// loop on its own real-time thread; statistics on request, the config file re-checked on
// SIGHUP), deactivate (after the final cycle drove the fail-safe current: the stop logged, the
// writer and the buses down) and report (statistics, the run's verdict). Under systemd it
// reports readiness, feeds the watchdog while the loop's cycles advance and keeps STATUS=
// current (telemetry::ServiceNotifier); supervisor transitions reach the log as they happen.
// Returns the process exit code. `unblock`, if given, is the set of signals the caller blocked
// so that the threads started here inherit it; it is unblocked on the calling thread once they run.
int run_controller(const config::ControllerConfig& config, const RunOptions& options,
                   runtime::ProcessSignals& signals, std::FILE* out, const sigset_t* unblock = nullptr);

}  // namespace mrd::firmware
