#include "sim/damper_plant.hpp"

namespace mrd::sim {

DamperPlant::DamperPlant(const model::DamperModel& truth, double lvdt_noise_rms, unsigned seed)
    : physics_(truth), rng_(seed), noise_(0.0, lvdt_noise_rms) {}

PlantReading DamperPlant::step(double displacement, double velocity, double coil_current) {
  const model::ObserverEstimate truth = physics_.step(displacement, velocity, coil_current);
  const double noise = noise_.stddev() > 0.0 ? noise_(rng_) : 0.0;
  return {displacement, displacement + noise, truth.B, truth.force};
}

}  // namespace mrd::sim
