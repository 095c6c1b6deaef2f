#include "tests/support/simulated_rig_run.hpp"

#include <cmath>

#include "sim/damper_plant.hpp"

namespace mrd::tools {

record::RecordedRun simulate_run(const model::DamperModel& truth, const SimulatedRunOptions& options) {
  sim::DamperPlant plant(truth, options.lvdt_noise, options.seed);
  record::RecordedRun run;
  run.name = "simulated";
  run.sample_rate = options.sample_rate;
  run.coil_source = "simulated current";
  const auto n = static_cast<std::size_t>(std::llround(options.duration * options.sample_rate)) + 1;
  for (auto* v : {&run.time, &run.displacement, &run.coil, &run.force, &run.velocity, &run.B})
    v->reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / options.sample_rate;
    const double v = options.motion.velocity(t);
    const bool high = std::fmod(t, options.current_period) >= 0.5 * options.current_period;
    const double current = high ? options.current_high : options.current_low;
    const sim::PlantReading reading = plant.step({.displacement = options.motion.displacement(t), .velocity = v, .coil_current = current});
    run.time.push_back(t);
    run.displacement.push_back(reading.lvdt_displacement);
    run.coil.push_back(current);
    run.force.push_back(reading.force);
    run.velocity.push_back(v);
    run.B.push_back(reading.B);
  }
  return run;
}

}  // namespace mrd::tools
