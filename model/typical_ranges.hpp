#pragma once

// What real MR dampers and their materials show (docs/MODEL.md, "Typical ranges"). A value
// outside is legal, and validate() only warns, but it is suspect: a fit that ran to an edge (a
// viscosity of 1e-54 Pa s with the yield term doing the viscous work), or a unit slip.
// mrd-residual's base fit searches inside these, so one source holds both.
namespace mrd::model {

struct TypicalRange {
  double lo;
  double hi;
  [[nodiscard]] constexpr bool holds(double v) const { return v >= lo && v <= hi; }
};

// J-A material (Eq. 1-10): soft irons to hard steels.
inline constexpr TypicalRange kTypicalPinningOverShape{0.05, 20.0};  // k / a
inline constexpr TypicalRange kTypicalReversibility{0.01, 0.95};     // c
inline constexpr TypicalRange kTypicalMeanFieldGain{0.0, 0.85};      // alpha Ms / 3a, short of the fold at 1
// The fluid: Eq. 13's yield exponent (power laws of MR fluids run about 0.3-1.2; the paper's is
// 0.5811) and the Herschel-Bulkley flow index. The viscosity [Pa s]: carrier oils have 0.01-1,
// but a lumped fit (mrd-residual keeps the starting damper's geometry and scales it) carries the
// geometry's mismatch in it too, so only a collapse far below any liquid, or more than the
// model accepts, is suspect.
inline constexpr TypicalRange kTypicalFieldExponent{0.25, 1.25};
inline constexpr TypicalRange kTypicalFlowIndex{0.5, 1.5};
inline constexpr TypicalRange kTypicalViscosity{1e-6, 1e3};
// The sign smoothing's velocity [m/s]: above about 50 mm/s the yield term turns viscous.
inline constexpr TypicalRange kTypicalSignVelocity{1e-6, 0.05};

}  // namespace mrd::model
