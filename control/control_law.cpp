#include "control/control_law.hpp"

namespace mrd::control {

ValidationReport validate(const ControlLawConfig& config) {
  ValidationReport report;
  report.merge(model::validate(config.damper), "damper");
  report.merge(model::validate(config.schedule), "schedule");
  report.require_positive("limits.max_current", config.limits.max_current);
  // Negative down to -max_current for a bipolar driver, which can clear remanence.
  report.require_in_range("limits.min_current", config.limits.min_current,
                          -config.limits.max_current, config.limits.max_current, false);
  report.require_positive("limits.slew_rate", config.limits.slew_rate);
  report.require_positive("limits.tolerance", config.limits.tolerance);
  report.require_positive("observer.sample_period", config.observer.sample_period);
  report.require_positive("observer.velocity_cutoff_frequency",
                          config.observer.velocity_cutoff_frequency);
  // Always: a bad value in the file is an error even while no load cell reads it.
  report.merge(validate(config.load_cell), "load_cell");
  if (report.ok() && config.limits.min_current >= config.limits.max_current) {
    report.error("limits.min_current", "must be below limits.max_current");
  }
  return report;
}

ControlLaw::ControlLaw(const ControlLawConfig& config)
    : schedule_(config.schedule),
      observer_(config.damper, config.observer),
      compensator_(observer_.magnetics(),
                   model::TargetCurve(observer_.magnetics(), config.limits.max_current, config.target),
                   config.limits, config.observer.sample_period),
      uncompensated_(config.limits.min_current, config.limits.max_current, config.limits.slew_rate,
                     config.observer.sample_period),
      compensate_(config.compensate_hysteresis) {
  if (config.mode == ControlMode::kForce) force_.emplace(observer_, config.limits, config.force);
  // The gate's force range is the model's maximum yield force.
  if (force_ && config.has_load_cell) {
    correction_.emplace(config.load_cell, force_->max_yield_force(), config.observer.sample_period);
  }
}

ScaleUpdate ControlLaw::correct_force_scale(LoadCellStatus status, double measured) {
  if (!correction_) return ScaleUpdate::kWaiting;
  const model::ObserverEstimate& e = observation_.estimate;
  const ScaleUpdate u = correction_->update({.status = status,
                                            .measured = measured,
                                            .predicted = e.force,
                                            .viscous = observer_.damper().force({.velocity = e.velocity, .yield_stress = 0.0}),
                                            .velocity = e.velocity});
  observer_.set_yield_scale(correction_->scale());
  return u;
}

const ControlLaw::Observation& ControlLaw::observe(const model::Measurement& m) {
  observation_.scheduled_current = schedule_.update(m.displacement);
  observation_.estimate = observer_.step(m);
  return observation_;
}

ControlLaw::Command ControlLaw::command(double demand) {
  if (force_) {
    // The velocity over the coming period is taken as the observer's now (docs/FORCE-CONTROL.md).
    const model::ForceCommand f =
        force_->step({.force = demand, .velocity = observation_.estimate.velocity}, observer_);
    return {.current = f.current,
            .target_B = f.target_B,
            .demand = demand,
            .yield_force = f.yield_force,
            .clipped = f.clipped,
            .reached = f.reached};
  }
  const double scheduled = observation_.scheduled_current;
  if (compensate_) {
    const double current = compensator_.command(scheduled, observer_.magnetics());  // sets target_B()
    return {.current = current, .target_B = compensator_.target_B()};
  }
  return {.current = uncompensated_.update(scheduled), .target_B = compensator_.target().B(scheduled)};
}

}  // namespace mrd::control
