#pragma once

#include <cmath>
#include <algorithm>
#include <optional>
#include <span>
#include <string>
#include "common/validation_report.hpp"
#include "model/effects/effect_traits.hpp"

namespace mrd::model {

// Eq. 11-12's parts of the fluid force that hook 4 of the effect chain (effect_chain.hpp) may
// reshape. Named, so that a swapped part does not compile.
struct FluidForceParts {
  double yield_force = 0.0;    // F_y + F_s, what the sign term carries [N]
  double sign_term = 0.0;      // s(v / v_s) [-]
  double viscous_force = 0.0;  // c0 v, after the effects' viscosity factor [N]
  double velocity = 0.0;       // [m/s]
};

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

  bool operator==(const PreyieldHysteresisParams&) const = default;
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
  // The fluid force [N] above, from Eq. 11-12's parts (the velocity is step()'s).
  [[nodiscard]] double fluid_force(const FluidForceParts& f) const {
    return f.yield_force * (f.sign_term + fraction_ * (z_ * inv_z_max_ - f.sign_term)) + stiffness_ * z_ +
           f.viscous_force;
  }
  [[nodiscard]] double z() const { return z_; }
  [[nodiscard]] double z_max() const { return z_max_; }
  void reset() { z_ = 0.0; }
  // The next steps' length [s], for samples taken unevenly (EffectChain::set_step).
  void set_step(double dt) { period_ = dt; }

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

// The descriptor (effect_traits.hpp): the share w and z_max, with A = 1, n = 2, beta = gamma
// (a run cannot tell them apart), z_max from 0.2 % to 20 % of the stroke.
struct PreyieldHysteresisEffect : EffectTraitsBase<PreyieldHysteresisParams> {
  using Element = PreyieldHysteresis;
  static constexpr std::string_view kName = "preyield_hysteresis";
  static constexpr std::string_view kSeparatedBy =
      "small-amplitude motion that never reaches the stroke-end threshold (pre-yield acts at every reversal)";
  // Hook (effect_chain.hpp): the fluid force with z, in place of Eq. 11-12's.
  static double fluid_force(Element& e, const FluidForceParts& parts) {
    e.step(parts.velocity);
    return e.fluid_force(parts);
  }

  template <typename Visitor>
  static void fields(Params& p, Visitor&& v) {
    v("enabled", p.enabled);
    v("A", p.A);
    v("beta", p.beta);
    v("gamma", p.gamma);
    v("n", p.n);
    v("stiffness", p.stiffness);
    v("yield_fraction", p.yield_fraction);
    v("max_substeps", p.max_substeps);
  }

  static constexpr std::array kSearch = {
      SearchCoordinate{"yield fraction w", [](const RunScales&) { return 0.0; },
                       [](const RunScales&) { return 1.0; }},
      SearchCoordinate{"log10 z_max [m]",
                       [](const RunScales& s) { return std::log10(std::max(1e-6, 2e-3 * s.stroke)); },
                       [](const RunScales& s) { return std::log10(0.2 * s.stroke); }}};
  static void apply(Params& p, std::span<const double> x, const RunScales&);
  static void coordinates(const Params& p, const RunScales&, std::span<double> x) {
    x[0] = p.yield_fraction;
    x[1] = std::log10(p.z_max());
  }
  static void scale_force(Params& p, double a) { p.stiffness *= a; }
  static std::optional<std::string> implausible(const Params& p, const RunScales&);
  template <typename Visitor>
  static void report(const Params& p, Visitor&& v) {
    v("yield_fraction", p.yield_fraction);
    v("z_max_m", p.z_max());
  }
  static Params nominal(DamperClassId damper) {
    // A Bouc-Wen loop that saturates at z_max = (A / (beta + gamma))^(1/n) and carries a tenth
    // of the yield force.
    const double z_max = damper == DamperClassId::k50kN ? 0.5e-3 : 0.2e-3;
    Params p;
    p.A = 1.0;
    p.n = 2.0;
    p.beta = 0.5 / (z_max * z_max);
    p.gamma = p.beta;
    p.yield_fraction = 0.1;
    return p;
  }
  static void resize(Params& p, double size, double /*dissipated_energy*/) {
    p.enabled = true;
    p.yield_fraction = std::min(size * p.yield_fraction, 1.0);
  }
  static std::string size_summary(const Params& p);
};
}  // namespace mrd::model
