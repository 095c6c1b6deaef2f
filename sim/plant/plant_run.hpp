#pragma once

#include <signal.h>

#include "runtime/rt_main.hpp"
#include "sim/plant/plant_config.hpp"
#include "sim/plant/rig.hpp"

namespace mrd::plant {

// mrd-plant's run, in the controller's lifecycle steps: configure (memory locked, the log open,
// the buses started), activate (what runs printed), run (the rig stepped in real time until the
// duration ends or a stop signal, each period's LVDT, current, demand and load cell served on
// the buses), deactivate (the buses and the log closed) and report (statistics, the log's and
// the faults' time origins). Returns the exit code. `unblock`: the signals the caller blocked
// before the bus threads start, unblocked on the calling thread once they run.
int run_plant(const PlantConfig& config, Rig& rig, runtime::ProcessSignals& signals, const sigset_t* unblock);

}  // namespace mrd::plant
