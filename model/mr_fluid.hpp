#pragma once

#include "common/validation_report.hpp"

namespace mrd::model {

// MR fluid properties behind Eq. 12-13. Defaults are the paper's Table 3 (mid-range).
struct MrFluid {
  double viscosity = 2.25;             // eta, zero-field viscosity [Pa s]
  double volume_fraction = 0.40;       // V, particle volume fraction [-]
  double particle_diameter = 1.5e-6;   // rho in Eq. 13, particle diameter [m]
  double particle_saturation = 2.1;    // Ms in Eq. 13, mu0*Ms of the particles [T] (docs/MODEL.md)
};

ValidationReport validate(const MrFluid& fluid);

// Eq. 13: yield stress [Pa] from the gap induction |B| [T].
//   tau_y = 146960 B^0.5811 V^1.706 rho^0.2 Ms^0.8 + 1083.2 V - 287.03
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
  //   |B| = ((tau - offset) / gain)^(1 / 0.5811).
  // Below the zero-field stress (the offset, when it is positive) no field gives less, so it is
  // 0; so is a NaN. A negative offset makes every B up to the root of Eq. 13 give 0 Pa: the
  // least of them, 0, answers tau = 0, and just above it the root. No upper clamp: the
  // caller bounds tau by what its maximum current gives.
  [[nodiscard]] double induction(double tau) const;
  // The yield stress at B = 0 [Pa]: the least the fluid has.
  [[nodiscard]] double zero_field_stress() const { return (*this)(0.0); }

 private:
  double field_gain_;  // 146960 V^1.706 rho^0.2 Ms^0.8 [Pa / T^0.5811]
  double offset_;      // 1083.2 V - 287.03 [Pa]
};

}  // namespace mrd::model
