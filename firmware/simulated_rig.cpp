#include "firmware/simulated_rig.hpp"

#include <chrono>

namespace mrd::firmware {

SimulatedRig::SimulatedRig(const SimulationConfig& config, const model::DamperModel& truth,
                           double sample_period, hal::mock::MockHal& hal)
    : profile_{config.amplitude, config.frequency},
      plant_(truth, sim::PlantSettings{sample_period, config.lvdt_noise, 0.0, config.seed}),
      hal_(hal) {}

void SimulatedRig::advance(hal::Timestamp now) {
  if (!start_) start_ = now;
  hal_.clock.set(now);
  const double t = std::chrono::duration<double>(now - *start_).count();
  last_ = plant_.step(profile_.displacement(t), profile_.velocity(t), hal_.driver.last_setpoint());
  hal_.lvdt.set_truth(last_.lvdt_displacement);
}

}  // namespace mrd::firmware
