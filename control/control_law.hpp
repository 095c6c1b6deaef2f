#pragma once

#include "common/validation_report.hpp"
#include <cstdint>
#include <limits>
#include <optional>

#include "control/force_scale_correction.hpp"
#include "model/current_schedule.hpp"
#include "model/damper_model.hpp"
#include "model/force_inverse.hpp"
#include "model/hysteresis_compensator.hpp"
#include "model/observer.hpp"
#include "model/slew_limiter.hpp"
#include "model/target_curve.hpp"

namespace mrd::control {

// What the law tracks: the paper's Table 4 current schedule on the displacement, or the force an
// outer controller demands each period (issue 18, docs/FORCE-CONTROL.md).
enum class ControlMode : std::uint8_t { kTable4, kForce };

struct ControlLawConfig {
  ControlMode mode = ControlMode::kTable4;
  model::ForceInverseOptions force;  // force mode only
  // Force mode's optional load-cell feedback (backends.load_cell; the loader sets has_load_cell).
  bool has_load_cell = false;
  ForceScaleSettings load_cell;
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
//              command: in table4 mode the schedule's, compensated for hysteresis (or only
//              slew-limited); in force mode the one model::ForceInverse finds for the demand
//              at the observer's velocity, slew-limited;
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
    double target_B = 0.0;  // what the schedule (or the force inverse) intends [T]
    // Force mode only (NaN and false in table4 mode):
    double demand = std::numeric_limits<double>::quiet_NaN();       // the force asked for [N]
    double yield_force = std::numeric_limits<double>::quiet_NaN();  // Eq. 12 at target_B [N]
    bool clipped = false;  // the demand pushed with the motion or lay beyond the damper's range
    bool reached = false;  // the J-A search met its tolerance
  };

  explicit ControlLaw(const ControlLawConfig& config);

  // `m.coil_current` is the current that flowed this period (measured, or the last command).
  const Observation& observe(const model::Measurement& m);
  // After observe(), this period's command; `demand` [N] is force mode's (ignored in table4).
  Command command(double demand = 0.0);
  // Force mode with a load cell, after observe() and only while the law drives the coil: this
  // period's load cell against this period's estimate moves the observer's yield scale, which
  // the command's inverse then uses (ForceScaleCorrection). kWaiting without a load cell.
  ScaleUpdate correct_force_scale(LoadCellStatus status, double measured);
  // The model's yield force scale now: 1 without a load cell.
  [[nodiscard]] double force_scale() const { return observer_.yield_scale(); }
  // Null without a load cell.
  [[nodiscard]] const ForceScaleCorrection* force_scale_correction() const {
    return correction_ ? &*correction_ : nullptr;
  }
  void hold(double current) {
    compensator_.reset(current);
    uncompensated_.reset(current);
    if (force_) force_->hold(current);
  }

  [[nodiscard]] ControlMode mode() const { return force_ ? ControlMode::kForce : ControlMode::kTable4; }
  [[nodiscard]] const model::Observer& observer() const { return observer_; }
  // Force mode's inverse (nullptr in table4 mode), for its search statistics.
  [[nodiscard]] const model::ForceInverse* force_inverse() const { return force_ ? &*force_ : nullptr; }

 private:
  model::CurrentSchedule schedule_;
  model::Observer observer_;
  model::HysteresisCompensator compensator_;
  model::SlewLimiter uncompensated_;
  std::optional<model::ForceInverse> force_;  // force mode only
  std::optional<ForceScaleCorrection> correction_;  // force mode with a load cell only
  bool compensate_;
  Observation observation_;
};

}  // namespace mrd::control
