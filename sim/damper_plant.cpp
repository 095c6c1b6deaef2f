#include "sim/damper_plant.hpp"

namespace mrd::sim {

DamperPlant::DamperPlant(const model::DamperModel& truth, double lvdt_noise_rms, unsigned seed)
    : DamperPlant(truth, PlantSettings{.sample_period = 1e-3, .lvdt_noise_rms = lvdt_noise_rms, .seed = seed}) {}

PlantReading DamperPlant::step(const PlantInput& in) {
  const model::ObserverEstimate truth =
      physics_.step({.displacement = in.displacement, .velocity = in.velocity, .coil_current = in.coil_current});
  const double noise = noise_.stddev() > 0.0 ? noise_(rng_) : 0.0;
  const double force_noise = force_noise_.stddev() > 0.0 ? force_noise_(force_rng_) : 0.0;
  const double sensed = delayed_ ? lvdt_delay_.step(in.displacement) : in.displacement;
  PlantReading r;
  r.true_displacement = in.displacement;
  r.lvdt_displacement = sensed + noise;
  r.B = truth.B;
  r.force = truth.force;
  r.measured_force = truth.force + force_noise;
  r.sensor_velocity = delayed_ ? velocity_delay_.step(in.velocity) : in.velocity;
  r.coil_current = physics_.effects().active() ? physics_.effects().coil_current() : in.coil_current;
  r.temperature = physics_.effects().temperature();
  return r;
}

}  // namespace mrd::sim
