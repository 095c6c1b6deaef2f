#include "model/bingham_damper.hpp"

#include <cmath>
#include <numbers>

#include "model/saturating_shape.hpp"
#include "model/typical_ranges.hpp"

namespace mrd::model {

ValidationReport validate(const DamperGeometry& g) {
  ValidationReport report;
  // Bounds past the largest (seismic) dampers, so that only nonsense fails.
  report.require_positive("piston_area", g.piston_area, 1.0);  // [m^2]
  report.require_positive("pole_length", g.pole_length, 1.0);  // [m]
  report.require_positive("gap", g.gap, 0.01);                  // [m]
  report.require_positive("piston_diameter", g.piston_diameter, 1.0);  // [m]
  report.require_positive("sign_velocity_scale", g.sign_velocity_scale, 1.0);  // [m/s]
  report.require_in_range("sign_shape", g.sign_shape, -1.0, 1.0, false);
  report.require_in_range("seal_friction", g.seal_friction, 0.0, 1e7, false);  // [N]
  if (report.ok() && g.gap >= 0.5 * g.piston_diameter) {
    report.error("gap", "must be much smaller than the piston radius (Eq. 12 assumes a thin gap)");
  }
  if (report.ok()) {
    report.expect_typical("sign_velocity_scale", g.sign_velocity_scale, kTypicalSignVelocity.lo, kTypicalSignVelocity.hi,
                          "dampers' yield transitions [m/s]");
  }
  return report;
}

BinghamDamper::BinghamDamper(const DamperGeometry& g, double viscosity, double flow_index)
    : yield_gain_(3.0 * g.piston_area * g.pole_length / g.gap),
      viscous_coefficient_(12.0 * viscosity * g.pole_length * g.piston_area * g.piston_area /
                           (std::numbers::pi * g.piston_diameter * g.gap * g.gap * g.gap)),
      inv_sign_velocity_(1.0 / g.sign_velocity_scale),
      sign_shape_(g.sign_shape),
      flow_index_(flow_index),
      seal_friction_(g.seal_friction) {}

double BinghamDamper::sign_term(double velocity) const {
  return saturating_shape(velocity * inv_sign_velocity_, sign_shape_);
}

double BinghamDamper::viscous_force(double velocity) const {
  if (flow_index_ == 1.0) return viscous_coefficient_ * velocity;  // Eq. 12
  const double ratio = std::fabs(velocity) * (1.0 / kFlowReferenceVelocity);
  return std::copysign(viscous_coefficient_ * kFlowReferenceVelocity * std::pow(ratio, flow_index_), velocity);
}

double BinghamDamper::force(const FlowState& flow) const {
  // Eq. 12 with the regularised sgn of Eq. 11.
  return sliding_force(flow.yield_stress) * sign_term(flow.velocity) + viscous_force(flow.velocity);
}

double BinghamDamper::yield_stress_for(const ForceAtVelocity& wanted) const {
  const double sign = sign_term(wanted.velocity);
  if (sign == 0.0) return (std::fabs(wanted.force) - seal_friction_) / yield_gain_;
  // Eq. 12 for tau_y
  return (wanted.force - viscous_force(wanted.velocity)) / (yield_gain_ * sign) - seal_friction_ / yield_gain_;
}

}  // namespace mrd::model
