#pragma once

#include <signal.h>

#include <atomic>
#include <cstdint>
#include <cstdio>

#include "config/controller_config.hpp"

namespace mrd::firmware {

// Flags the signal handlers set (async-signal-safe: lock-free atomics only).
struct ControllerSignals {
  std::atomic<bool> stop{false};         // SIGTERM, SIGINT
  std::atomic<bool> print_stats{false};  // SIGUSR1
};

struct RunOptions {
  double duration_s = 0.0;  // 0: until SIGTERM/SIGINT
  bool bench = false;       // also print the latency histograms
};

// mrd-controller's run: builds the back ends, the loop and the telemetry writer, runs the loop
// on its own real-time thread, prints statistics on request and at exit, and on stop drives the
// fail-safe current before anything is torn down. Returns the process exit code.
// `unblock`, if given, is the set of signals the caller blocked so that the threads started
// here inherit it; it is unblocked on the calling thread once they run.
int run_controller(const config::ControllerConfig& config, const RunOptions& options,
                   ControllerSignals& signals, std::FILE* out, const sigset_t* unblock = nullptr);

}  // namespace mrd::firmware
