#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "model/bingham_damper.hpp"
#include "model/mr_fluid.hpp"

namespace {

using mrd::model::BinghamDamper;
using mrd::model::DamperGeometry;
using mrd::model::MrFluid;
using mrd::model::YieldStress;

// Hand-computed: 146960 * B^0.5811 * 0.4^1.706 * 1.5^0.2 * 2.1^0.8 + 1083.2*0.4 - 287.03
TEST(YieldStressEq13, MatchesHandComputedValues) {
  const YieldStress tau(MrFluid{2.25, 0.40, 1.5e-6, 2.1});
  EXPECT_NEAR(tau(1.0), 60583.845, 0.01);
  EXPECT_NEAR(tau(0.5), 40545.997, 0.01);
  EXPECT_NEAR(tau(-0.5), 40545.997, 0.01);  // depends on |B|
  EXPECT_NEAR(tau(0.0), 1083.2 * 0.4 - 287.03, 1e-9);
}

TEST(YieldStressEq13, IsClampedAtZeroWhereTheFitGoesNegative) {
  const YieldStress thin(MrFluid{2.25, 0.20, 1.5e-6, 2.1});  // 1083.2*0.2 - 287.03 < 0
  EXPECT_EQ(thin(0.0), 0.0);
  EXPECT_GT(thin(0.1), 0.0);
}

// Eq. 13 inverted (YieldStress::induction). The hand-computed 60583.845 Pa is 1 T; dtau/dB is
// 0.5811 * 60437.6 Pa/T there, so 0.01 Pa of rounding is 3e-7 T.
TEST(YieldStressEq13, InductionInvertsTheHandComputedValues) {
  const YieldStress tau(MrFluid{2.25, 0.40, 1.5e-6, 2.1});
  EXPECT_NEAR(tau.induction(60583.845), 1.0, 1e-6);
  EXPECT_NEAR(tau.induction(40545.997), 0.5, 1e-6);
}

TEST(YieldStressEq13, InductionRoundTripsOverTheRange) {
  const YieldStress tau(MrFluid{});
  double worst = 0.0;
  for (double B = 1e-6; B <= 3.0; B *= 1.1) {
    worst = std::max(worst, std::fabs(tau.induction(tau(B)) - B) / B);
    const double stress = tau.zero_field_stress() + 1e5 * B / 3.0;  // the other way round
    EXPECT_NEAR(tau(tau.induction(stress)), stress, 1e-10 * stress);
  }
  EXPECT_LT(worst, 1e-11);
}

// Eq. 13 is a power law above its offset: doubling tau - offset multiplies B by 2^(1/0.5811).
TEST(YieldStressEq13, InductionFollowsThePowerLawAboveTheOffset) {
  const YieldStress tau(MrFluid{});
  const double offset = 1083.2 * 0.40 - 287.03;
  for (const double above : {10.0, 1e3, 5e4}) {
    EXPECT_NEAR(tau.induction(offset + 2.0 * above) / tau.induction(offset + above), std::pow(2.0, 1.0 / 0.5811),
                1e-12);
  }
}

// No field gives less than the zero-field stress: at and below it, and for bad input, B = 0.
// A fluid whose offset is negative gives 0 Pa up to the root of Eq. 13; just above 0 Pa the
// inverse is that root, where the forward equation is back at 0 Pa.
TEST(YieldStressEq13, InductionIsZeroAtAndBelowTheZeroFieldStress) {
  const YieldStress tau(MrFluid{});
  EXPECT_EQ(tau.zero_field_stress(), 1083.2 * 0.40 - 287.03);
  EXPECT_EQ(tau.induction(tau.zero_field_stress()), 0.0);
  EXPECT_EQ(tau.induction(0.0), 0.0);
  EXPECT_EQ(tau.induction(-1e4), 0.0);
  EXPECT_EQ(tau.induction(std::nan("")), 0.0);
  // By hand: gain 146960 * 0.2^1.706 * 1.5^0.2 * 2.1^0.8 = 18528 Pa/T^0.5811, offset -70.394 Pa,
  // root (70.394 / 18528)^(1/0.5811) = 6.84e-5 T.
  const YieldStress thin(MrFluid{2.25, 0.20, 1.5e-6, 2.1});
  EXPECT_EQ(thin.induction(0.0), 0.0);
  const double root = thin.induction(1e-9);
  EXPECT_NEAR(root, 6.84e-5, 0.01e-5);
  EXPECT_NEAR(thin(root), 0.0, 1e-8);
  EXPECT_EQ(thin(0.99 * root), 0.0);
  EXPECT_GT(thin(1.01 * root), 0.0);
}

// The tabulated |B|^0.5811 against long double pow, relative, over 2^-40..2^40 T: the table's
// range (2^-32..2^32) and the std::pow fallback on both sides, on a log grid that does not
// repeat. The reference exponent is the double 0.5811 (0.5811L differs by 1e-17, which moves
// B^p by 1e-15 at 2^-32 T).
TEST(YieldStressEq13, TabulatedPowerMatchesStdPow) {
  const auto exponent = static_cast<long double>(0.5811);
  double max_relative_error = 0.0;
  for (int i = 0; i <= 400'000; ++i) {
    const double B = std::exp2(-40.0 + 80.0 * i / 400'000.0 + 1e-9 * (i % 7));
    const long double reference = std::pow(static_cast<long double>(B), exponent);
    const double error = static_cast<double>(
        std::fabs((mrd::model::eq13_field_power(B) - reference) / reference));
    max_relative_error = std::max(max_relative_error, error);
  }
  EXPECT_LT(max_relative_error, 1e-15);
  std::printf("tabulated |B|^0.5811: max relative error %.2g\n", max_relative_error);
  EXPECT_EQ(mrd::model::eq13_field_power(0.0), 0.0);
  EXPECT_EQ(mrd::model::eq13_field_power(1.0), 1.0);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(mrd::model::eq13_field_power(inf), inf);
  EXPECT_TRUE(std::isnan(mrd::model::eq13_field_power(std::nan(""))));
  const double denormal = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(mrd::model::eq13_field_power(denormal), std::pow(denormal, 0.5811));
}

// Geometry: Ap = 5.89e-3 m^2, L = 0.06 m, hd = 1.5 mm, D = 0.1 m, eta = 2.25 Pa s.
// 3 Ap L / hd = 0.7068 m^2; 12 eta L Ap^2 / (pi D hd^3) = 53005.624 N s/m.
TEST(BinghamEq12, CoefficientsMatchHandComputedValues) {
  const BinghamDamper damper(DamperGeometry{}, 2.25);
  EXPECT_NEAR(damper.yield_force(1.0), 0.7068, 1e-12);
  EXPECT_NEAR(damper.viscous_coefficient(), 53005.624, 1e-3);
}

TEST(BinghamEq12, ForceMatchesHandComputedValues) {
  const BinghamDamper damper(DamperGeometry{}, 2.25);
  EXPECT_NEAR(damper.force({.velocity = 0.1, .yield_stress = 5e4}), 40640.562, 1e-3);
  EXPECT_NEAR(damper.force({.velocity = -0.1, .yield_stress = 5e4}), -40640.562, 1e-3);
  // Inside the regularisation band: tanh(0.5) of the yield force.
  EXPECT_NEAR(damper.force({.velocity = 0.5e-3, .yield_stress = 5e4}), 16357.723, 1e-3);
  EXPECT_EQ(damper.force({.velocity = 0.0, .yield_stress = 5e4}), 0.0);
}

// Eq. 12 inverted (BinghamDamper::yield_stress_for), against the forward hand values above:
// at 0.1 m/s tanh is 1 to 1e-86, so tau = (F - c0 v) / (3 Ap L / hd); in the band, tanh(0.5).
TEST(BinghamEq12, YieldStressForInvertsTheHandComputedForces) {
  const BinghamDamper damper(DamperGeometry{}, 2.25);
  EXPECT_NEAR(damper.yield_stress_for({.force = 40640.562, .velocity = 0.1}), 5e4, 2e-3);
  EXPECT_NEAR(damper.yield_stress_for({.force = -40640.562, .velocity = -0.1}), 5e4, 2e-3);
  EXPECT_NEAR(damper.yield_stress_for({.force = 16357.723, .velocity = 0.5e-3}), 5e4, 2e-3);
  // The viscous force alone needs none (c0 is rounded to 1e-3 N s/m: 1e-4 N, 1.4e-4 Pa).
  EXPECT_NEAR(damper.yield_stress_for({.force = 53005.624 * 0.1, .velocity = 0.1}), 0.0, 2e-4);
}

TEST(BinghamEq12, YieldStressForRoundTripsThroughTheForce) {
  const BinghamDamper damper(DamperGeometry{}, 2.25);
  for (const double v : {-0.3, -2e-3, -1e-4, 1e-5, 7e-4, 0.05}) {
    for (const double tau : {0.0, 146.25, 1e4, 6e4}) {
      EXPECT_NEAR(damper.yield_stress_for({.force = damper.force({.velocity = v, .yield_stress = tau}), .velocity = v}), tau, 1e-9 * (tau + 1e4)) << v << " " << tau;
    }
  }
}

// Negative where no yield stress can give the force: pushing with the motion, or less than c0 v.
// At rest the sign is undefined; the documented choice holds |F| (the fluid at rest holds up to
// the yield force in either direction).
TEST(BinghamEq12, YieldStressForIsNegativeForForcesNoFieldGivesAndHoldsAtRest) {
  const BinghamDamper damper(DamperGeometry{}, 2.25);
  EXPECT_LT(damper.yield_stress_for({.force = -1e4, .velocity = 0.05}), 0.0);
  EXPECT_LT(damper.yield_stress_for({.force = 1e4, .velocity = -0.05}), 0.0);
  EXPECT_LT(damper.yield_stress_for({.force = 0.5 * 53005.624 * 0.05, .velocity = 0.05}), 0.0);
  EXPECT_NEAR(damper.yield_stress_for({.force = 7068.0, .velocity = 0.0}), 1e4, 1e-9);
  EXPECT_NEAR(damper.yield_stress_for({.force = -7068.0, .velocity = 0.0}), 1e4, 1e-9);
}

TEST(BinghamEq12, SignRegularisationReachesThe995PercentPointAtThreeScales) {
  DamperGeometry g;
  g.sign_velocity_scale = 2e-3;
  const BinghamDamper damper(g, 0.0 + 1e-12);
  const double yield = damper.yield_force(1e4);
  EXPECT_NEAR(damper.force({.velocity = 6e-3, .yield_stress = 1e4}) / yield, std::tanh(3.0), 1e-6);
}

}  // namespace
