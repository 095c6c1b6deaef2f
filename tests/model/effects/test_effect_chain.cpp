// The effect chain on its own: which hooks run for what the set enables, against closed forms.
// Nothing enabled: every hook is the identity. coil_lag: the exact first-order step response
// at the sample instants, 1 - exp(-k T / tau). gas_spring: F0 + k x added. An effect left off
// is never stepped.
#include "model/effects/effect_chain.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace effect_chain_test {

using mrd::model::CoilLagEffect;
using mrd::model::EffectChain;
using mrd::model::EffectSet;
using mrd::model::ForceState;
using mrd::model::GasSpringEffect;

constexpr double kPeriod = 1e-3;

TEST(EffectChain, WithNothingEnabledEveryHookIsTheIdentity) {
  EffectChain chain(EffectSet{}, kPeriod);
  EXPECT_FALSE(chain.active());
  EXPECT_EQ(chain.coil_current(0.7), 0.7);
  EXPECT_EQ(chain.yield_factor(), 1.0);
  EXPECT_EQ(chain.force_factor(0.01), 1.0);
  EXPECT_EQ(chain.added_force(ForceState{.displacement = 0.01, .velocity = 0.1}), 0.0);
}

TEST(EffectChain, CoilLagFollowsTheExactFirstOrderStep) {
  EffectSet set;
  set.get<CoilLagEffect>() = {.enabled = true, .time_constant = 10e-3};
  EffectChain chain(set, kPeriod);
  ASSERT_TRUE(chain.active());
  for (int k = 1; k <= 50; ++k) {
    const double flowing = chain.coil_current(1.0);
    EXPECT_NEAR(flowing, 1.0 - std::exp(-k * kPeriod / 10e-3), 1e-12) << k;
    EXPECT_EQ(chain.coil_current(), flowing);
  }
  EXPECT_EQ(chain.added_force(ForceState{.displacement = 0.02}), 0.0);  // the spring is off
  chain.reset();
  EXPECT_NEAR(chain.coil_current(1.0), 1.0 - std::exp(-0.1), 1e-12);  // from rest again
}

TEST(EffectChain, AGasSpringAddsItsPreloadAndStiffnessAndLeavesTheCurrentAlone) {
  EffectSet set;
  set.get<GasSpringEffect>() = {.enabled = true, .preload = 100.0, .stiffness = 2e4};
  EffectChain chain(set, kPeriod);
  ASSERT_TRUE(chain.active());
  EXPECT_DOUBLE_EQ(chain.added_force(ForceState{.displacement = 0.01}), 300.0);
  EXPECT_DOUBLE_EQ(chain.added_force(ForceState{.displacement = -0.01}), -100.0);
  EXPECT_EQ(chain.coil_current(0.4), 0.4);  // no lag enabled: what is commanded flows
  EXPECT_EQ(chain.force_factor(0.01), 1.0);
}

}  // namespace effect_chain_test
