#include <gtest/gtest.h>

#include <cmath>

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

// Geometry: Ap = 5.89e-3 m^2, L = 0.06 m, hd = 1.5 mm, D = 0.1 m, eta = 2.25 Pa s.
// 3 Ap L / hd = 0.7068 m^2; 12 eta L Ap^2 / (pi D hd^3) = 53005.624 N s/m.
TEST(BinghamEq12, CoefficientsMatchHandComputedValues) {
  const BinghamDamper damper(DamperGeometry{}, 2.25);
  EXPECT_NEAR(damper.yield_force(1.0), 0.7068, 1e-12);
  EXPECT_NEAR(damper.viscous_coefficient(), 53005.624, 1e-3);
}

TEST(BinghamEq12, ForceMatchesHandComputedValues) {
  const BinghamDamper damper(DamperGeometry{}, 2.25);
  EXPECT_NEAR(damper.force(0.1, 5e4), 40640.562, 1e-3);
  EXPECT_NEAR(damper.force(-0.1, 5e4), -40640.562, 1e-3);
  // Inside the regularisation band: tanh(0.5) of the yield force.
  EXPECT_NEAR(damper.force(0.5e-3, 5e4), 16357.723, 1e-3);
  EXPECT_EQ(damper.force(0.0, 5e4), 0.0);
}

TEST(BinghamEq12, SignRegularisationReachesThe995PercentPointAtThreeScales) {
  DamperGeometry g;
  g.sign_velocity_scale = 2e-3;
  const BinghamDamper damper(g, 0.0 + 1e-12);
  const double yield = damper.yield_force(1e4);
  EXPECT_NEAR(damper.force(6e-3, 1e4) / yield, std::tanh(3.0), 1e-6);
}

}  // namespace
