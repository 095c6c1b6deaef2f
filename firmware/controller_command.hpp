#pragma once

#include <string>

#include "firmware/controller.hpp"
#include "runtime/rt_main.hpp"

namespace mrd::firmware {

// mrd-controller's command line, as its main parsed it.
struct ControllerCommand {
  std::string config_path;     // --config; empty: the embedded config
  std::string check_path;      // --check-config
  std::string telemetry_path;  // --telemetry: exactly this file
  double rate = 0.0;           // --rate [Hz]; 0: loop.rate
  bool print_default = false;  // --print-default-config
  bool probe = false;          // --probe
  RunOptions options;          // --duration, --bench
};

// Carries the command out: prints the embedded config, checks a config file, probes the buses,
// or loads the config, applies the command line's overrides and runs the controller with the
// process's signal handlers on `signals`. Returns the exit code.
int run_command(const ControllerCommand& command, runtime::ProcessSignals& signals);

}  // namespace mrd::firmware
