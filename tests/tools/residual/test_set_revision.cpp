// The set revision's choice of swaps (tools/residual/set_revision.cpp): an effect is swapped only
// for a rival outside the set, so a rival accepted in a later round is never named twice (the
// random-damper study's coil_lag+preyield_hysteresis-203 once ended "preyield_hysteresis
// coil_lag coil_lag").
#include "tools/residual/set_revision.hpp"

#include <gtest/gtest.h>

#include "model/effects/effect_set.hpp"

namespace {

using mrd::model::find_effect;
using mrd::tools::search::AcceptedSet;
using mrd::tools::search::rivals_outside_the_set;

TEST(SetRevision, ARivalAlreadyInTheSetIsNoSwap) {
  const auto* air = find_effect("stroke_end_air");
  const auto* lag = find_effect("coil_lag");
  const auto* gas = find_effect("gas_spring");
  const auto* preyield = find_effect("preyield_hysteresis");
  ASSERT_TRUE(air && lag && gas && preyield);
  AcceptedSet set;
  set.effects = {preyield, air, lag};
  set.rivals = {{}, {lag, gas}, {}};
  EXPECT_EQ(rivals_outside_the_set(set, 1), (mrd::tools::search::Effects{gas}));
  EXPECT_TRUE(rivals_outside_the_set(set, 0).empty());
  set.rivals[1] = {lag};
  EXPECT_TRUE(rivals_outside_the_set(set, 1).empty());
}

}  // namespace
