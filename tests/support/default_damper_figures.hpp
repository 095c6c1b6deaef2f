#pragma once

namespace mrd::test {

// The default damper (docs/MODEL.md) worked by hand, as references the code's formulas are
// checked against. Eq. 12's viscous coefficient c0 = 12 eta L Ap^2 / (pi D hd^3) with
// eta 2.25 Pa s, L 0.06 m, Ap 5.89e-3 m^2, D 0.1 m, hd 1.5e-3 m; its zero-field yield force,
// Eq. 13 at B = 0 (1083.2 V - 287.03 = 146.25 Pa at V = 0.4) times 3 Ap L / hd = 0.7068 m^2.
inline constexpr double kDefaultViscousCoefficient = 53005.624;  // [N s/m]
inline constexpr double kDefaultZeroFieldYieldForce = 103.3695;  // [N]

}  // namespace mrd::test
