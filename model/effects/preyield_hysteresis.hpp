#pragma once

#include "common/validation_report.hpp"

namespace mrd::model {

// Pre-yield force-velocity hysteresis: Bouc-Wen's evolutionary variable z (Bouc 1967, Wen 1976,
// in the form Spencer et al. 1997 use for MR dampers),
//   dz/dt = A v - beta |v| |z|^(n-1) z - gamma v |z|^n,
// carries the part of the yield force that needs some travel after a reversal to build up. The
// Bingham yield force switches with tanh(v / v_s) as soon as v changes sign; in a real damper
// the fluid in the gap first strains elastically, so near v = 0 the force lags the velocity and
// the force-velocity curve opens into a loop. The fluid force becomes
//   F = F_y [(1 - w) tanh(v / v_s) + w z / z_max] + alpha z + c0 v,
// w = `yield_fraction` the share of the yield force F_y carried by z, alpha = `stiffness` a
// field-independent Bouc-Wen force (Spencer's alpha_a). With A > 0, beta > 0 and
// -beta < gamma <= beta, z stays within +-z_max, z_max = (A / (beta + gamma))^(1/n)
// (Ikhouane, Manosa and Rodellar 2007); after a reversal z covers most of its range within a
// travel of about z_max / A.
struct PreyieldHysteresisParams {
  bool enabled = false;
  double A = 1.0;               // [-]
  double beta = 5e5;            // [m^-n]
  double gamma = 5e5;           // [m^-n]
  double n = 2.0;               // [-], >= 1
  double stiffness = 0.0;       // alpha [N/m]
  double yield_fraction = 0.5;  // w [-], in [0, 1]
  int max_substeps = 64;        // real-time bound on the work per step

  // (A / (beta + gamma))^(1/n) [m]; with the defaults 1 mm.
  [[nodiscard]] double z_max() const;
};

ValidationReport validate(const PreyieldHysteresisParams& params);

// Integration. Within one period the velocity is taken as constant, so z follows
//   dz/dx = A - s beta |z|^(n-1) z - gamma |z|^n,   s = sign(v), over dx = v T,
// an autonomous equation in the travel. Its stiffness is at most n A / z_max, so the travel of
// one period is cut into sub-steps of at most z_max / (2 n A) (|lambda h| <= 0.5) and each is
// one classical RK4 step; a sub-step can then neither oscillate nor overshoot. The exact z never
// leaves [-z_max, z_max] and moves monotonically towards s z_max, so z is clamped to that range
// after each sub-step. Beyond max_substeps (a very fast stroke) the sub-steps get longer; the
// clamp still bounds z. A non-finite z restarts from 0. No heap, no exceptions.
class PreyieldHysteresis {
 public:
  PreyieldHysteresis(const PreyieldHysteresisParams& params, double sample_period);

  // Advances z over one period at `velocity` [m/s]; returns z [m].
  double step(double velocity);
  // The fluid force [N] above, from the Bingham yield force F_y [N], its sign term
  // tanh(v / v_s) and the viscous force c0 v [N].
  [[nodiscard]] double fluid_force(double yield_force, double sign_term, double viscous_force) const {
    return yield_force * (sign_term + fraction_ * (z_ * inv_z_max_ - sign_term)) + stiffness_ * z_ +
           viscous_force;
  }
  [[nodiscard]] double z() const { return z_; }
  [[nodiscard]] double z_max() const { return z_max_; }
  void reset() { z_ = 0.0; }

 private:
  [[nodiscard]] double slope(double z, double s) const;  // dz/dx

  double A_;
  double beta_;
  double gamma_;
  double n_;
  bool square_;  // n == 2: |z|^n without pow
  double stiffness_;
  double fraction_;
  double period_;
  double z_max_;
  double inv_z_max_;
  double inv_max_substep_;  // 1 / longest sub-step travel [1/m]
  int max_substeps_;
  double z_ = 0.0;
};

}  // namespace mrd::model
