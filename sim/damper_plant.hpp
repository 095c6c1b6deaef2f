#pragma once

#include <random>

#include "model/damper_model.hpp"
#include "model/observer.hpp"

namespace mrd::sim {

struct PlantReading {
  double true_displacement = 0.0;  // [m]
  double lvdt_displacement = 0.0;  // what the sensor reports [m]
  double B = 0.0;                  // [T]
  double force = 0.0;              // [N]
};

// The simulated damper: true J-A + Bingham physics driven by the true velocity, and an LVDT
// with white noise. The plant knows its velocity exactly; the controller does not.
class DamperPlant {
 public:
  DamperPlant(const model::DamperModel& truth, double lvdt_noise_rms, unsigned seed);

  PlantReading step(double displacement, double velocity, double coil_current);

 private:
  model::Observer physics_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> noise_;
};

}  // namespace mrd::sim
