#include "model/observer.hpp"

namespace mrd::model {

Observer::Observer(const DamperModel& model, const ObserverSettings& settings)
    : magnetics_(model.jiles_atherton, model.circuit, model.integration),
      yield_stress_(model.fluid),
      damper_(model.geometry, model.fluid.viscosity),
      velocity_filter_(settings.sample_period, settings.velocity_cutoff_frequency) {}

ObserverEstimate Observer::step(double displacement, double coil_current) {
  return step(displacement, velocity_filter_.update(displacement), coil_current);
}

ObserverEstimate Observer::step(double /*displacement*/, double velocity, double coil_current) {
  estimate_.B = magnetics_.apply_current(coil_current);
  estimate_.yield_stress = yield_stress_(estimate_.B);
  estimate_.velocity = velocity;
  estimate_.force = damper_.force(velocity, estimate_.yield_stress);
  return estimate_;
}

void Observer::reset() {
  magnetics_.demagnetise();
  velocity_filter_.reset();
  estimate_ = {};
}

}  // namespace mrd::model
