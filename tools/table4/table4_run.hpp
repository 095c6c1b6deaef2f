#pragma once

#include <vector>

#include "control/control_law.hpp"
#include "model/damper_model.hpp"
#include "sim/displacement_profile.hpp"

namespace mrd::tools {

// A simulated Table 4 test: the rig moves the damper sinusoidally, the control law schedules
// and (optionally) compensates the current, and a plant with the same physics responds.
struct Table4RunOptions {
  sim::SineProfile profile;
  int cycles = 3;               // the first is excluded from the error figures (virgin curve)
  double lvdt_noise_rms = 5e-6; // [m]
  unsigned seed = 1;
  control::ControlLawConfig controller;
  model::DamperModel plant;     // the simulated damper's true physics
};

struct ErrorFigures {
  double rms = 0.0;
  double max = 0.0;
};

struct Table4Sample {
  double time = 0.0;               // [s]
  double displacement = 0.0;       // true [m]
  double scheduled_current = 0.0;  // [A]
  double command_current = 0.0;    // [A]
  double target_B = 0.0;           // intended by the schedule [T]
  double B = 0.0;                  // plant [T]
  double force = 0.0;              // plant [N]
  double intended_force = 0.0;     // force at the intended B [N]
  double observer_force = 0.0;     // the observer's estimate [N]
};

struct Table4RunResult {
  ErrorFigures B_tracking;        // plant B - intended B [T]
  ErrorFigures force_vs_intended; // plant force - intended force [N]
  ErrorFigures observer_force;    // observer force - plant force [N]
  double peak_force = 0.0;        // max |plant force| [N]
  std::vector<Table4Sample> trace;
};

Table4RunResult run_table4(const Table4RunOptions& options);

}  // namespace mrd::tools
