#pragma once

#include <string>

#include "runtime/rt_main.hpp"

namespace mrd::plant {

// mrd-plant's command line, as its main parsed it: a config to check, or one to run with the
// command line's overrides of it.
struct PlantCommand {
  std::string config_path;   // --config
  std::string check_path;    // --check-config
  double duration = -1.0;    // --duration [s]; < 0: plant.duration
  int port = -2;             // --port; < 0: modbus.port
  std::string log_path;      // --log; empty: plant.log
  bool no_log = false;       // --no-log
};

// Carries the command out: checks a config file, or loads the config, builds the rig (a
// playback file read) and runs the plant with the process's signal handlers on `signals`.
// Returns the exit code.
int run_command(const PlantCommand& command, runtime::ProcessSignals& signals);

}  // namespace mrd::plant
