// The base model's shapes beyond the paper's (docs/MODEL.md, "Shapes of another damper"): each
// against an analytic limit or a closed form it must meet, not against its own code.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "model/bingham_damper.hpp"
#include "model/mr_fluid.hpp"
#include "model/saturating_shape.hpp"

namespace {

using mrd::model::BinghamDamper;
using mrd::model::DamperGeometry;
using mrd::model::MrFluid;
using mrd::model::saturating_shape;
using mrd::model::YieldStress;

double slope_at_rest(double shape) {
  const double h = 1e-6;
  return (saturating_shape(h, shape) - saturating_shape(-h, shape)) / (2.0 * h);
}

TEST(SignShape, EveryShapeIsOddWithSlopeOneAtRestAndReachesOne) {
  for (const double q : {-1.0, -0.4, 0.0, 0.3, 1.0, 1.5, 2.0}) {
    EXPECT_NEAR(slope_at_rest(q), 1.0, 1e-6) << q;
    for (const double x : {0.05, 0.7, 3.0}) EXPECT_DOUBLE_EQ(saturating_shape(-x, q), -saturating_shape(x, q));
    EXPECT_NEAR(saturating_shape(1e5, q), 1.0, 1e-4) << q;
    EXPECT_LE(std::fabs(saturating_shape(2.0, q)), 1.0);
  }
}

TEST(SignShape, HoldsTanhAtanAndTheKneeAtItsMarks) {
  // tanh at 0: at x = 3 it is 0.99505 (the 99.5 % point at three scales).
  EXPECT_NEAR(saturating_shape(3.0, 0.0), 0.995055, 1e-6);
  // atan at -1: its tail 1 - s(x) approaches 4 / (pi^2 x), an algebraic 1/x decay that tanh has not.
  const double x = 1000.0;
  EXPECT_NEAR((1.0 - saturating_shape(x, -1.0)) * std::numbers::pi * std::numbers::pi * x / 4.0, 1.0, 1e-3);
  EXPECT_LT(1.0 - saturating_shape(20.0, 0.0), 1e-15);
  // The knee at +1: linear to within 0.1 % up to x = 0.5, flat to within 0.1 % from x = 2.5.
  EXPECT_NEAR(saturating_shape(0.5, 1.0) / 0.5, 1.0, 1e-3);
  EXPECT_NEAR(saturating_shape(2.5, 1.0), 1.0, 1e-3);
  EXPECT_LT(saturating_shape(0.5, 0.0) / 0.5, 0.95);  // tanh is already bending there
}

TEST(SignShape, IsMonotoneInTheShapeBetweenTheForms) {
  // At x = 1.5 the knee is nearly flat, tanh at 0.905, atan lower: the blend moves between them.
  double previous = -1.0;
  for (double q = -1.0; q <= 1.0; q += 0.25) {
    const double s = saturating_shape(1.5, q);
    EXPECT_GT(s, previous) << q;
    previous = s;
  }
}

// Past +1 the knee sharpens: at 2 a power law capped hard, min(x, 1), to 0.6 % at the corner,
// continuous with the order-8 knee at 1 and rising at the corner all the way.
TEST(SignShape, PastOneTheKneeSharpensTowardsTheCorner) {
  double worst = 0.0;
  for (double x = 0.0; x <= 4.0; x += 0.01) worst = std::max(worst, std::fabs(saturating_shape(x, 2.0) - std::min(x, 1.0)));
  EXPECT_LT(worst, 0.006);
  EXPECT_GT(worst, 0.004);  // the corner itself is not reached
  EXPECT_GT(std::fabs(saturating_shape(1.0, 1.0) - 1.0), 0.08);  // the order-8 knee is 8 % short of it
  for (const double x : {0.3, 1.0, 1.7}) EXPECT_NEAR(saturating_shape(x, 1.0 + 1e-9), saturating_shape(x, 1.0), 1e-8);
  double previous = saturating_shape(1.0, 1.0);
  for (double q = 1.25; q <= 2.0; q += 0.25) {
    EXPECT_GT(saturating_shape(1.0, q), previous) << q;
    previous = saturating_shape(1.0, q);
  }
}

TEST(SignShape, InverseRoundTripsEveryShapeAndRefusesTheCeiling) {
  EXPECT_NEAR(mrd::model::saturating_shape_inverse(std::tanh(0.8), 0.0), 0.8, 1e-12);
  // atan's closed-form inverse at q = -1: x = (2 / pi) tan(pi y / 2).
  EXPECT_NEAR(mrd::model::saturating_shape_inverse(0.9, -1.0), 2.0 / std::numbers::pi * std::tan(0.45 * std::numbers::pi),
              1e-9);
  for (const double q : {-0.5, 0.4, 1.0}) {
    for (const double x : {0.01, 0.9, 3.0}) {
      EXPECT_NEAR(mrd::model::saturating_shape_inverse(saturating_shape(x, q), q), x, 1e-9 * (1.0 + x)) << q << " " << x;
    }
  }
  // Past the knee the shape is flat to the last bit soon after x = 1: round trips up to there.
  for (const double q : {1.3, 2.0}) {
    for (const double x : {0.01, 0.9, 1.05}) {
      EXPECT_NEAR(mrd::model::saturating_shape_inverse(saturating_shape(x, q), q), x, 1e-9 * (1.0 + x)) << q << " " << x;
    }
  }
  EXPECT_TRUE(std::isinf(mrd::model::saturating_shape_inverse(1.0, 0.5)));
  // The knee is written in 1/x beyond 1: no overflow to 0 or NaN at the ends of the doubles.
  EXPECT_EQ(saturating_shape(1e300, 1.0), 1.0);
  EXPECT_EQ(saturating_shape(-std::numeric_limits<double>::infinity(), 1.0), -1.0);
  EXPECT_EQ(mrd::model::saturating_shape_inverse(0.0, 0.5), 0.0);
}

TEST(HerschelBulkley, IsBinghamAtIndexOneAndAPowerLawOtherwise) {
  const DamperGeometry g;
  const BinghamDamper bingham(g, 2.25);
  const BinghamDamper thinning(g, 2.25, 0.6);
  const double c0 = bingham.viscous_coefficient();
  EXPECT_DOUBLE_EQ(bingham.viscous_force(0.037), c0 * 0.037);
  // At the reference velocity every index gives c0 v_ref; doubling v multiplies the force by 2^n.
  EXPECT_NEAR(thinning.viscous_force(mrd::model::kFlowReferenceVelocity), c0 * mrd::model::kFlowReferenceVelocity,
              1e-9 * c0);
  EXPECT_NEAR(thinning.viscous_force(0.08) / thinning.viscous_force(0.04), std::pow(2.0, 0.6), 1e-12);
  EXPECT_DOUBLE_EQ(thinning.viscous_force(-0.05), -thinning.viscous_force(0.05));
  // Shear thinning: more force than Bingham below v_ref, less above.
  EXPECT_GT(thinning.viscous_force(0.01), bingham.viscous_force(0.01));
  EXPECT_LT(thinning.viscous_force(0.5), bingham.viscous_force(0.5));
}

TEST(SealFriction, AddsAConstantForceAgainstTheMotionAndInvertsWithTheYieldStress) {
  DamperGeometry g;
  g.seal_friction = 120.0;
  const BinghamDamper with(g, 2.25);
  const BinghamDamper without(DamperGeometry{}, 2.25);
  // At 0 A and well past v_s the difference is the friction; against the motion both ways.
  EXPECT_NEAR(with.force({.velocity = 0.1, .yield_stress = 0.0}) - without.force({.velocity = 0.1, .yield_stress = 0.0}), 120.0, 1e-9);
  EXPECT_NEAR(with.force({.velocity = -0.1, .yield_stress = 0.0}) - without.force({.velocity = -0.1, .yield_stress = 0.0}), -120.0, 1e-9);
  for (const double tau : {0.0, 5e3, 4e4}) {
    for (const double v : {-0.2, -0.003, 0.0005, 0.05}) {
      EXPECT_NEAR(with.yield_stress_for({.force = with.force({.velocity = v, .yield_stress = tau}), .velocity = v}), tau, 1e-6 * (tau + 1.0)) << v << " " << tau;
    }
  }
}

TEST(YieldExponent, FollowsItsPowerLawAboveTheOffsetAndInverts) {
  MrFluid fluid;
  fluid.field_exponent = 0.9;
  const YieldStress tau(fluid);
  const double offset = tau.zero_field_stress();
  EXPECT_NEAR((tau(0.8) - offset) / (tau(0.4) - offset), std::pow(2.0, 0.9), 1e-12);
  EXPECT_NEAR(tau.induction(tau(0.63)), 0.63, 1e-12);
  // The paper's exponent takes the tabulated power and agrees with std::pow.
  const YieldStress paper{MrFluid{}};
  MrFluid nearly;
  nearly.field_exponent = std::nextafter(mrd::model::kEq13FieldExponent, 1.0);
  EXPECT_NEAR(paper(0.7), YieldStress(nearly)(0.7), 1e-9 * paper(0.7));
}

TEST(YieldSaturation, IsThePowerLawBelowBsAndACeilingAboveAndInverts) {
  MrFluid power;
  power.field_exponent = 1.0;
  MrFluid bent = power;
  bent.saturation_induction = 0.8;
  const YieldStress plain(power), saturating(bent);
  const double offset = plain.zero_field_stress();
  const double gain = plain(1.0) - offset;  // [Pa / T] at n = 1
  // n = 1: the tanh law tau = gain B_s tanh(B / B_s), exactly.
  for (const double B : {0.01, 0.4, 0.8, 1.6}) {
    EXPECT_NEAR(saturating(B) - offset, gain * 0.8 * std::tanh(B / 0.8), 1e-9 * gain) << B;
  }
  // Far below B_s the power law; far above, the ceiling gain B_s^n.
  EXPECT_NEAR((saturating(0.008) - offset) / (plain(0.008) - offset), 1.0, 1e-4);
  EXPECT_NEAR(saturating(40.0) - offset, gain * 0.8, 1e-9 * gain);
  EXPECT_NEAR(saturating.induction(saturating(0.9)), 0.9, 1e-9);
  // Above the ceiling no B gives the stress: the answer is finite and gives the ceiling.
  const double beyond = saturating.induction(offset + 2.0 * gain * 0.8);
  EXPECT_TRUE(std::isfinite(beyond));
  EXPECT_NEAR(saturating(beyond) - offset, gain * 0.8, 1e-6 * gain);
}

// Eq. 13 with exponent n and no ceiling: tau = offset + gain B^n, the reference for a ceiling.
struct PowerLaw {
  double offset, gain;  // [Pa], [Pa / T^n]
};
PowerLaw plain_power_law(double n) {
  MrFluid fluid;
  fluid.field_exponent = n;
  const YieldStress plain(fluid);
  return {plain.zero_field_stress(), plain(1.0) - plain.zero_field_stress()};
}

// A fluid of exponent n whose yield stress saturates at B_s with a knee of shape q.
MrFluid saturating_fluid(double n, double b_s, double q) {
  MrFluid fluid;
  fluid.field_exponent = n;
  fluid.saturation_induction = b_s;
  fluid.saturation_shape = q;
  return fluid;
}

TEST(YieldSaturation, AtAnotherExponentBendsAtBsToThePowerNAndInvertsThroughTheBlend) {
  const YieldStress tau(saturating_fluid(0.8, 0.9, 0.5));
  const auto [offset, gain] = plain_power_law(0.8);  // gain [Pa / T^0.8]
  // The ceiling is gain B_s^0.8 (not gain B_s), reached far above B_s.
  EXPECT_NEAR(tau(500.0) - offset, gain * std::pow(0.9, 0.8), 1e-6 * gain);
  // At B = B_s: (B / B_s)^n = 1, the blend of tanh(1) and the knee's 1 / 2^(1/8) half and half.
  EXPECT_NEAR(tau(0.9) - offset, gain * std::pow(0.9, 0.8) * (0.5 * std::tanh(1.0) + 0.5 / std::pow(2.0, 0.125)),
              1e-9 * gain);
  for (const double B : {0.05, 0.6, 1.4}) EXPECT_NEAR(tau.induction(tau(B)), B, 1e-9) << B;
}

// A power law capped hard (the sharpest knee, q = 2): within 0.6 % of min(gain B^n, gain B_s^n)
// everywhere, and the induction comes back from the stress below the cap, and at the cap.
TEST(YieldSaturation, AtTheSharpestKneeIsAPowerLawCappedAtBs) {
  const YieldStress tau(saturating_fluid(0.7, 0.6, 2.0));
  const auto [offset, gain] = plain_power_law(0.7);  // gain [Pa / T^0.7]
  const double cap = gain * std::pow(0.6, 0.7);
  for (const double B : {0.05, 0.3, 0.55, 0.6, 0.65, 1.2, 3.0}) {
    EXPECT_NEAR(tau(B) - offset, std::min(gain * std::pow(B, 0.7), cap), 0.006 * cap) << B;
  }
  for (const double B : {0.05, 0.3, 0.59}) EXPECT_NEAR(tau.induction(tau(B)), B, 1e-9) << B;
  for (const double q : {1.5, 2.0}) {
    const YieldStress at(saturating_fluid(0.7, 0.6, q));
    const double beyond = at.induction(offset + 1.5 * cap);  // above the ceiling: finite, at the cap
    EXPECT_TRUE(std::isfinite(beyond)) << q;
    EXPECT_NEAR(at(beyond) - offset, cap, 1e-6 * cap) << q;
  }
}

TEST(ShapeParameters, OutsideTheirPhysicalRangesAreErrorsNamingTheField) {
  MrFluid fluid;
  fluid.field_exponent = 3.0;
  fluid.flow_index = 0.1;
  fluid.saturation_induction = 0.01;
  const auto r = mrd::model::validate(fluid);
  EXPECT_TRUE(r.mentions("saturation_induction"));
  EXPECT_TRUE(r.mentions("field_exponent"));
  EXPECT_TRUE(r.mentions("flow_index"));
  MrFluid capped;
  capped.saturation_shape = 1.5;  // the yield ceiling's knee may sharpen past 1; the sign's may not
  EXPECT_TRUE(mrd::model::validate(capped).ok());
  capped.saturation_shape = 2.5;
  EXPECT_TRUE(mrd::model::validate(capped).mentions("saturation_shape"));
  DamperGeometry g;
  g.sign_shape = 1.5;
  g.seal_friction = -1.0;
  const auto q = mrd::model::validate(g);
  EXPECT_TRUE(q.mentions("sign_shape"));
  EXPECT_TRUE(q.mentions("seal_friction"));
}

}  // namespace
