#include "model/bingham_damper.hpp"

#include <cmath>
#include <numbers>

namespace mrd::model {

ValidationReport validate(const DamperGeometry& g) {
  ValidationReport report;
  report.require_positive("piston_area", g.piston_area);
  report.require_positive("pole_length", g.pole_length);
  report.require_positive("gap", g.gap);
  report.require_positive("piston_diameter", g.piston_diameter);
  report.require_positive("sign_velocity_scale", g.sign_velocity_scale);
  if (report.ok() && g.gap >= 0.5 * g.piston_diameter) {
    report.error("gap", "must be much smaller than the piston radius (Eq. 12 assumes a thin gap)");
  }
  return report;
}

BinghamDamper::BinghamDamper(const DamperGeometry& g, double viscosity)
    : yield_gain_(3.0 * g.piston_area * g.pole_length / g.gap),
      viscous_coefficient_(12.0 * viscosity * g.pole_length * g.piston_area * g.piston_area /
                           (std::numbers::pi * g.piston_diameter * g.gap * g.gap * g.gap)),
      inv_sign_velocity_(1.0 / g.sign_velocity_scale) {}

double BinghamDamper::sign_term(double velocity) const { return std::tanh(velocity * inv_sign_velocity_); }

double BinghamDamper::force(double velocity, double yield_stress) const {
  // Eq. 12 with the regularised sgn of Eq. 11.
  return yield_gain_ * yield_stress * std::tanh(velocity * inv_sign_velocity_) +
         viscous_coefficient_ * velocity;
}

double BinghamDamper::yield_stress_for(double force, double velocity) const {
  const double sign = sign_term(velocity);
  if (sign == 0.0) return std::fabs(force) / yield_gain_;
  return (force - viscous_coefficient_ * velocity) / (yield_gain_ * sign);  // Eq. 12 for tau_y
}

}  // namespace mrd::model
