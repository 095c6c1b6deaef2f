#pragma once

#include "model/bingham_damper.hpp"
#include "model/hysteresis_compensator.hpp"
#include "model/mr_fluid.hpp"
#include "model/observer.hpp"
#include "model/slew_limiter.hpp"

namespace mrd::model {

// What an outer controller asks of the damper this period. The force carries the sign of the
// motion it resists, as Eq. 11-12's does: F v > 0 dissipates, the only force a semi-active
// damper can give.
struct ForceDemand {
  double force = 0.0;     // [N]
  double velocity = 0.0;  // piston velocity now [m/s]
};

struct ForceCommand {
  double current = 0.0;      // to the driver [A]
  double target_B = 0.0;     // the gap induction aimed at [T]
  double yield_force = 0.0;  // 3 Ap L / hd tau_y at target_B [N] (Eq. 12), times the observer's yield scale
  // The demand was not one the damper can give at this velocity (it pushed with the motion,
  // asked for less than the zero-field force or more than the maximum current's, or was not
  // finite), so the nearest one was aimed at: the least force for the first three.
  bool clipped = false;
  bool reached = false;  // B reaches target_B within the tolerance by the end of the period
};

struct ForceInverseOptions {
  // Invert the coil lag the observer's model declares; off, the law commands the current it
  // wants to flow, blind to the lag.
  bool invert_coil_lag = true;
};

// The inverse model: demanded force and velocity -> the yield stress the Bingham model needs
// (Eq. 11-12) -> the induction that gives it (Eq. 13) -> the current that takes the J-A state
// there by the end of the period (Eq. 1-10, HysteresisCompensator::current_for) -> the command
// that makes that current flow through the coil lag. Bounded by the driver's range and slew.
// Worst case: HysteresisCompensator's (2 + max_iterations integrations of Eq. 10 over one
// period's reachable current) plus one pow, and for a fluid whose yield stress saturates with a
// blended knee (0 < |saturation_shape| < 1) the bisection of saturating_shape_inverse, at most
// 200 evaluations of the shape; no heap, no exceptions, no I/O.
class ForceInverse {
 public:
  // The inverse of `observer`'s model; step() must be given that observer, after its step.
  ForceInverse(const Observer& observer, const CompensatorLimits& limits,
               const ForceInverseOptions& options = {});

  ForceCommand step(const ForceDemand& demand, const Observer& observer);
  // The driver's command is set elsewhere (fail-safe, another mode): the slew limit continues
  // from it.
  void hold(double current) { driver_.reset(current); }

  // The yield force at the maximum current on the anhysteretic curve [N], of the model without
  // the observer's yield scale: demands beyond it times the scale are clipped.
  [[nodiscard]] double max_yield_force() const { return damper_.yield_force(max_yield_stress_); }
  [[nodiscard]] double last_command() const { return driver_.value(); }
  // Trial integrations of Eq. 10 in the last step (at most 2 + max_iterations).
  [[nodiscard]] int last_evaluations() const { return evaluations_; }

 private:
  // The model's yield stress to aim at [Pa] (before the observer's yield `scale`), within what
  // the fluid can give; sets `clipped`.
  double aimed_yield_stress(const ForceDemand& demand, double scale, bool& clipped) const;

  YieldStress yield_stress_;
  BinghamDamper damper_;
  HysteresisCompensator compensator_;
  SlewLimiter driver_;
  double sample_period_;
  double min_yield_stress_;  // at B = 0 (Eq. 13's offset) [Pa]
  double max_yield_stress_;  // at the maximum current [Pa]
  bool invert_coil_lag_;
  int evaluations_ = 0;
};

}  // namespace mrd::model
