#pragma once

#include "model/damper_model.hpp"
#include "model/effects/thermal_drift.hpp"
#include "model/observer.hpp"

namespace mrd::test {

// An independent "true" damper for the load-cell correction's tests: the default damper whose
// yield stress is `factor` of the model's, through model::ThermalDrift's linear law at the
// measured temperature that gives it (1 - k (T - T_ref)), its viscosity left alone. Nothing in
// it uses the observer's yield scale, which is what the correction moves.
inline model::Observer drifted_plant(double factor, double sample_period) {
  constexpr double kReference = 20.0;        // [degC], where the factors are 1
  constexpr double kYieldPerKelvin = 0.004;  // [1/K]
  model::DamperModel m;
  auto& drift = m.effects.get<model::ThermalDriftEffect>();
  drift.enabled = true;
  drift.reference_temperature = kReference;
  drift.yield_coefficient = kYieldPerKelvin;
  drift.viscosity_coefficient = 0.0;
  drift.min_factor = 0.01;
  model::Observer plant(m, {sample_period});
  plant.set_measured_temperature(kReference + (1.0 - factor) / kYieldPerKelvin);
  return plant;
}

}  // namespace mrd::test
