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
  // Velocity scale of the sgn() regularisation: sgn(v) ~ s(v / v_s), slope 1 / v_s at rest.
  double sign_velocity_scale = 1e-3;  // [m/s]
  // The shape s of that regularisation, q in [-1, 1] of model::saturating_shape: -1 atan,
  // 0 tanh (the default), +1 a sharp knee, the three forms seen in MR dampers.
  double sign_shape = 0.0;  // [-]
  // Seal friction: a force of fixed size against the motion, present with no field [N]. It is
  // what a damper holds at 0 A beyond Eq. 13's zero-field yield stress.
  double seal_friction = 0.0;  // [N]

  bool operator==(const DamperGeometry&) const = default;
};

// The viscous force's reference velocity [m/s]: with a Herschel-Bulkley flow index n != 1,
// c0 is the secant coefficient at this speed, F_v = c0 v_ref sgn(v) |v / v_ref|^n.
inline constexpr double kFlowReferenceVelocity = 0.1;

ValidationReport validate(const DamperGeometry& geometry);

// What Eq. 11-12 read: the piston's velocity and the fluid's yield stress.
struct FlowState {
  double velocity;      // [m/s]
  double yield_stress;  // [Pa]
};

// A force wanted at a velocity, for the inverse of Eq. 11-12.
struct ForceAtVelocity {
  double force;     // [N]
  double velocity;  // [m/s]
};

// Eq. 11-12 (Bingham): F = (3 Ap L / hd) tau_y sgn(v) + (12 eta L Ap^2 / (pi D hd^3)) v,
// generalised to a Herschel-Bulkley fluid (the viscous term c0 v_ref sgn(v) |v / v_ref|^n, the
// standard extension for MR fluids; exactly Eq. 12 at n = 1) and a seal friction F_s sgn(v).
// Eq. 12 writes the shear rate, but its viscous coefficient has units N s/m, so the rate it
// multiplies is the piston velocity v. sgn(v) is replaced by tanh(v / v_s): the exact sign
// jumps by the full yield force at v = 0, which makes the force of a noisy velocity estimate
// chatter and has no derivative for identification. At |v| = 3 v_s tanh reaches 0.995.
class BinghamDamper {
 public:
  BinghamDamper(const DamperGeometry& geometry, double viscosity, double flow_index = 1.0);

  // Damper force [N] from the velocity and the yield stress.
  [[nodiscard]] double force(const FlowState& flow) const;
  [[nodiscard]] double yield_force(double yield_stress) const { return yield_gain_ * yield_stress; }
  // Eq. 11-12 inverted: the yield stress [Pa] that gives `force` [N] at `velocity` [m/s],
  //   tau_y = (F - F_v(v)) / ((3 Ap L / hd) s(v / v_s)) - F_s / (3 Ap L / hd).
  // The force carries the sign of the motion it resists (F v > 0 dissipates). Negative when no
  // yield stress can give the force: when it asks the damper to push with the motion, or for
  // less than the viscous term c0 v alone gives. At v = 0 the sign term is 0 and any stress
  // gives no force; the fluid at rest holds up to the yield force either way, so the answer is
  // (|F| - F_s) / (3 Ap L / hd): the field is ready when the motion starts.
  [[nodiscard]] double yield_stress_for(const ForceAtVelocity& wanted) const;
  // The regularised sgn(v) of Eq. 11, s(v / v_s) of DamperGeometry::sign_shape (tanh at 0).
  [[nodiscard]] double sign_term(double velocity) const;
  // The viscous force [N]: c0 v for Bingham, c0 v_ref sgn(v) |v / v_ref|^n for Herschel-Bulkley.
  [[nodiscard]] double viscous_force(double velocity) const;
  // The yield force and the seal friction together, the force that s(v) carries [N].
  [[nodiscard]] double sliding_force(double yield_stress) const { return yield_gain_ * yield_stress + seal_friction_; }
  [[nodiscard]] double seal_friction() const { return seal_friction_; }
  [[nodiscard]] double viscous_coefficient() const { return viscous_coefficient_; }  // c0 [N s/m]

 private:
  double yield_gain_;           // 3 Ap L / hd [m^2]
  double viscous_coefficient_;  // 12 eta L Ap^2 / (pi D hd^3) [N s/m]
  double inv_sign_velocity_;
  double sign_shape_;
  double flow_index_;
  double seal_friction_;
};

}  // namespace mrd::model
