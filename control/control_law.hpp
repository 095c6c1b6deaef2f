#pragma once

#include "model/current_schedule.hpp"
#include "model/damper_model.hpp"
#include "model/hysteresis_compensator.hpp"
#include "model/observer.hpp"
#include "model/slew_limiter.hpp"
#include "model/target_curve.hpp"

namespace mrd::control {

struct ControlLawConfig {
  model::DamperModel damper;
  model::CurrentScheduleTable schedule;
  model::CompensatorLimits limits;
  model::ObserverSettings observer;
  model::TargetCurve::Kind target = model::TargetCurve::Kind::kAnhysteretic;
  bool compensate_hysteresis = true;
};

ValidationReport validate(const ControlLawConfig& config);

struct ControlOutput {
  double scheduled_current = 0.0;  // Table 4 [A]
  double command_current = 0.0;    // to the driver, after compensation and limits [A]
  double target_B = 0.0;           // what the schedule intends [T]
  model::ObserverEstimate estimate;
};

// Steps 3-4 of a control cycle: Table 4 schedule, observer, hysteresis compensation.
// Pure computation on validated inputs; the loop around it owns I/O and supervision.
class ControlLaw {
 public:
  explicit ControlLaw(const ControlLawConfig& config);

  // `coil_current` is the current that flowed this period (measured, or the last command).
  // With `velocity` the observer uses it; otherwise it filters the displacement.
  ControlOutput step(double displacement, double coil_current);
  // The same for a sample read over a bus, at its own timing (model::SampleTiming).
  ControlOutput step(double displacement, const model::SampleTiming& timing, double coil_current);
  ControlOutput step(double displacement, double velocity, double coil_current);

  // While the supervisor drives the coil itself (INIT, SAFE), restarts the slew limiters from
  // the current it drives, so the command continues from there when control resumes.
  void hold(double current) {
    compensator_.reset(current);
    uncompensated_.reset(current);
  }

  [[nodiscard]] const model::Observer& observer() const { return observer_; }

 private:
  ControlOutput decide(double scheduled, const model::ObserverEstimate& estimate);

  model::CurrentSchedule schedule_;
  model::Observer observer_;
  model::HysteresisCompensator compensator_;
  model::SlewLimiter uncompensated_;
  bool compensate_;
};

}  // namespace mrd::control
