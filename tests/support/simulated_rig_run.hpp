#pragma once

#include <cstdint>

#include "model/damper_model.hpp"
#include "sim/displacement_profile.hpp"
#include "record/recorded_run.hpp"

namespace mrd::tools {

// A run recorded on the simulated rig: a sine displacement, a coil current that steps
// between two levels (so the core walks minor loops), and the plant's force (sim/DamperPlant,
// the model's own physics, driven by the true velocity). A replay of it with the same model
// and the recorded velocity must predict the force exactly: the test that replay adds no
// error of its own. A test fixture: the runs the tools ship come from tools/simulation.
struct SimulatedRunOptions {
  double duration = 4.0;        // [s]
  double sample_rate = 1000.0;  // [Hz]
  sim::SineProfile motion{0.020, 1.0};
  double current_low = 0.0;     // [A]
  double current_high = 1.0;    // [A]
  double current_period = 0.7;  // [s], square wave, starting low; not a multiple of the motion's
  double lvdt_noise = 0.0;      // [m] RMS on the recorded displacement
  std::uint32_t seed = 1;
};

[[nodiscard]] record::RecordedRun simulate_run(const model::DamperModel& truth,
                                       const SimulatedRunOptions& options = {});

}  // namespace mrd::tools
