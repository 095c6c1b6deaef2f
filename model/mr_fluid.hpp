#pragma once

#include "common/validation_report.hpp"

namespace mrd::model {

// MR fluid properties behind Eq. 12-13. Defaults are the paper's Table 3 (mid-range).
struct MrFluid {
  double viscosity = 2.25;             // eta, zero-field viscosity [Pa s]
  double volume_fraction = 0.40;       // V, particle volume fraction [-]
  double particle_diameter = 1.5e-6;   // rho in Eq. 13, particle diameter [m]
  double particle_saturation = 2.1;    // Ms in Eq. 13, mu0*Ms of the particles [T] (docs/MODEL.md)
  // The exponent of B in Eq. 13 (the paper's fit: 0.5811). Another fluid's yield law has its own;
  // mrd-residual identifies it from a run. Physical range 0.2-1.5 (validate).
  double field_exponent = 0.5811;      // [-]
  // The induction B_s [T] at which the particles' own saturation bends the yield stress flat:
  // the B^n term becomes B_s^n s((|B| / B_s)^n), the power law below B_s and a ceiling above
  // it, s the saturating_shape of `saturation_shape` (-1 slow, 0 tanh, +1 a sharp knee, +2 nearly
  // a corner: a power law capped hard). 0 (the
  // default, and the paper's Eq. 13) is no saturation. Range 0.02-50 T.
  double saturation_induction = 0.0;   // [T]
  double saturation_shape = 0.0;       // [-], in [-1, 2]
  // Herschel-Bulkley flow index n: the viscous stress grows as |shear rate|^n (Bingham at n = 1,
  // shear thinning below). Physical range 0.3-2 (validate); MR fluids fit 0.5-1.5.
  double flow_index = 1.0;             // [-]

  bool operator==(const MrFluid&) const = default;
};

// The Eq. 13 exponent of the paper, for which the real-time power has its fast table.
inline constexpr double kEq13FieldExponent = 0.5811;

ValidationReport validate(const MrFluid& fluid);

// Eq. 13: yield stress [Pa] from the gap induction |B| [T].
//   tau_y = 146960 B^0.5811 V^1.706 rho^0.2 Ms^0.8 + 1083.2 V - 287.03
// with the exponent 0.5811 replaced by MrFluid::field_exponent when a fluid has another, and
// B^n by B_s^n s((B / B_s)^n) for a fluid whose yield stress saturates (saturation_induction).
// The fit takes rho in micrometres and Ms as mu0*Ms in tesla: with those units it gives
// 10-100 kPa at 1 T, the range of commercial MR fluids; SI metres or A/m would give
// values 1e3-1e5 times too large. Below V = 0.265 the constant term is negative, so the
// result is clamped at 0: a fluid cannot have negative yield stress.
// |B|^0.5811, the power in Eq. 13, for |B| >= 0. std::pow costs about a fifth of an observer
// step, so the real-time path reads it from tables: |B| = 2^e m with m in [1, 2), m^0.5811 from
// degree-7 Chebyshev interpolants on 16 intervals of m and 2^(0.5811 e) from a table, both
// computed at compile time in long double. Relative error below 1e-15, measured 6e-16 (about
// 3 units in the last place; test YieldStressEq13.TabulatedPowerMatchesStdPow). Outside
// 2^-32 <= |B| < 2^32 T, and for 0, inf and NaN, it is std::pow.
double eq13_field_power(double abs_B);

class YieldStress {
 public:
  explicit YieldStress(const MrFluid& fluid);
  [[nodiscard]] double operator()(double B) const;
  // Eq. 13 inverted: the least |B| [T] that gives the yield stress `tau` [Pa],
  //   |B| = ((tau - offset) / gain)^(1 / field_exponent), or with saturation
  //   |B| = B_s s^-1((tau - offset) / (gain B_s^n))^(1 / n); at or past the ceiling, the B
  //   within 1e-12 of it.
  // Below the zero-field stress (the offset, when it is positive) no field gives less, so it is
  // 0; so is a NaN. A negative offset makes every B up to the root of Eq. 13 give 0 Pa: the
  // least of them, 0, answers tau = 0, and just above it the root. No upper clamp: the
  // caller bounds tau by what its maximum current gives.
  [[nodiscard]] double induction(double tau) const;
  // The yield stress at B = 0 [Pa]: the least the fluid has.
  [[nodiscard]] double zero_field_stress() const { return (*this)(0.0); }

 private:
  double field_gain_;  // 146960 V^1.706 rho^0.2 Ms^0.8 [Pa / T^n]
  double offset_;      // 1083.2 V - 287.03 [Pa]
  double exponent_;    // field_exponent; the paper's takes the tabulated power
  bool paper_exponent_;
  double saturation_;       // B_s [T], 0 for none
  double saturated_power_;  // B_s^n
  double saturation_shape_;
};

}  // namespace mrd::model
