#pragma once

#include "common/validation_report.hpp"

namespace mrd::model {

// Flow-mode damper geometry of Eq. 12. Defaults describe a 50 kN class damper like the
// paper's MRD-SEU-D050 (the paper does not publish its geometry; see docs/MODEL.md).
struct DamperGeometry {
  double piston_area = 5.89e-3;    // Ap, effective piston area [m^2]
  double pole_length = 0.06;       // L, effective (magnetically active) length [m]
  double gap = 1.5e-3;             // hd, annular gap [m]
  double piston_diameter = 0.1;    // D [m]
  // Velocity scale of the sgn() regularisation: sgn(v) ~ tanh(v / v_s).
  double sign_velocity_scale = 1e-3;  // [m/s]
};

ValidationReport validate(const DamperGeometry& geometry);

// Eq. 11-12 (Bingham): F = (3 Ap L / hd) tau_y sgn(v) + (12 eta L Ap^2 / (pi D hd^3)) v.
// Eq. 12 writes the shear rate, but its viscous coefficient has units N s/m, so the rate it
// multiplies is the piston velocity v. sgn(v) is replaced by tanh(v / v_s): the exact sign
// jumps by the full yield force at v = 0, which makes the force of a noisy velocity estimate
// chatter and has no derivative for identification. At |v| = 3 v_s tanh reaches 0.995.
class BinghamDamper {
 public:
  BinghamDamper(const DamperGeometry& geometry, double viscosity);

  // Damper force [N] from velocity [m/s] and yield stress [Pa].
  [[nodiscard]] double force(double velocity, double yield_stress) const;
  [[nodiscard]] double yield_force(double yield_stress) const { return yield_gain_ * yield_stress; }
  // Eq. 11-12 inverted: the yield stress [Pa] that gives `force` [N] at `velocity` [m/s],
  //   tau_y = (F - c0 v) / ((3 Ap L / hd) tanh(v / v_s)).
  // The force carries the sign of the motion it resists (F v > 0 dissipates). Negative when no
  // yield stress can give the force: when it asks the damper to push with the motion, or for
  // less than the viscous term c0 v alone gives. At v = 0 the sign term is 0 and any stress
  // gives no force; the fluid at rest holds up to the yield force either way, so the answer is
  // |F| / (3 Ap L / hd): the field is ready when the motion starts.
  [[nodiscard]] double yield_stress_for(double force, double velocity) const;
  // The regularised sgn(v) of Eq. 11, tanh(v / v_s).
  [[nodiscard]] double sign_term(double velocity) const;
  [[nodiscard]] double viscous_coefficient() const { return viscous_coefficient_; }  // c0 [N s/m]

 private:
  double yield_gain_;           // 3 Ap L / hd [m^2]
  double viscous_coefficient_;  // 12 eta L Ap^2 / (pi D hd^3) [N s/m]
  double inv_sign_velocity_;
};

}  // namespace mrd::model
