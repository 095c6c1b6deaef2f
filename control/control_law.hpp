#pragma once

#include "common/validation_report.hpp"
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

// Steps 3 and 4 of a control cycle (docs/FIRMWARE.md), around the supervisor's decision:
//   observe(): the Table 4 schedule and the observer, every period, whoever drives the coil,
//              so the observer's J-A state follows the current that flows;
//   command(): then, only while the supervisor lets the law drive the coil, the current to
//              command: the schedule's, compensated for hysteresis (or only slew-limited);
//   hold():    while the supervisor drives the coil itself (INIT, SAFE), the law's slew
//              limiters follow that current, so the command continues from it when control
//              resumes.
// Pure computation on validated inputs; the loop around it owns I/O and supervision. No heap.
class ControlLaw {
 public:
  struct Observation {
    double scheduled_current = 0.0;  // Table 4 [A]
    model::ObserverEstimate estimate;
  };
  struct Command {
    double current = 0.0;   // to the driver, after compensation and limits [A]
    double target_B = 0.0;  // what the schedule intends [T]
  };

  explicit ControlLaw(const ControlLawConfig& config);

  // `m.coil_current` is the current that flowed this period (measured, or the last command).
  const Observation& observe(const model::Measurement& m);
  // After observe(), this period's command.
  Command command();
  void hold(double current) {
    compensator_.reset(current);
    uncompensated_.reset(current);
  }

  [[nodiscard]] const model::Observer& observer() const { return observer_; }

 private:
  model::CurrentSchedule schedule_;
  model::Observer observer_;
  model::HysteresisCompensator compensator_;
  model::SlewLimiter uncompensated_;
  bool compensate_;
  Observation observation_;
};

}  // namespace mrd::control
