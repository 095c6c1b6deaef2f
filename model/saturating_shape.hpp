#pragma once

namespace mrd::model {

// One family of odd, saturating shapes s(x; q), slope 1 at 0 and s -> 1 as x -> infinity, with
// q in [-1, 2] choosing how the approach to 1 goes: -1 the slow algebraic approach of
// (2/pi) atan(pi x / 2), 0 tanh(x), +1 a sharp knee x / (1 + |x|^8)^(1/8); in between, the
// blend of the two forms on its side; past +1 the knee x / (1 + |x|^m)^(1/m) of order
// m = 8 * 16^(q - 1), at 2 within 0.6 % of the corner min(x, 1) (a capped power law).
// Eq. 11's regularised sgn (DamperGeometry::sign_shape, -1..1) and the yield stress's
// saturation in B (MrFluid::saturation_shape, -1..2) take their shape from it.
double saturating_shape(double x, double q);

// The x >= 0 with saturating_shape(x, q) = y, for 0 <= y < 1: closed forms at q = -1, 0 and
// from +1 on, a bisection to the last bits between (no heap, at most 164 evaluations). y >= 1 has no answer:
// it returns +infinity.
double saturating_shape_inverse(double y, double q);

}  // namespace mrd::model
