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
      compensate_(config.compensate_hysteresis) {}

ControlOutput ControlLaw::step(double displacement, double coil_current) {
  const double scheduled = schedule_.update(displacement);
  return decide(scheduled, observer_.step(displacement, coil_current));
}

ControlOutput ControlLaw::step(double displacement, const model::SampleTiming& timing, double coil_current) {
  const double scheduled = schedule_.update(displacement);
  return decide(scheduled, observer_.step(displacement, timing, coil_current));
}

ControlOutput ControlLaw::step(double displacement, double velocity, double coil_current) {
  const double scheduled = schedule_.update(displacement);
  return decide(scheduled, observer_.step(displacement, velocity, coil_current));
}

ControlOutput ControlLaw::decide(double scheduled, const model::ObserverEstimate& estimate) {
  ControlOutput out;
  out.scheduled_current = scheduled;
  out.estimate = estimate;
  if (compensate_) {
    out.command_current = compensator_.command(scheduled, observer_.magnetics());
    out.target_B = compensator_.target_B();
  } else {
    out.command_current = uncompensated_.update(scheduled);
    out.target_B = compensator_.target().B(scheduled);
  }
  return out;
}

}  // namespace mrd::control
