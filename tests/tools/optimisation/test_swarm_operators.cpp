#include "tools/optimisation/swarm_operators.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tests/tools/optimisation/scripted_stream.hpp"

namespace {

using mrd::test::ScriptedStream;
using mrd::tools::Bounds;
using mrd::tools::Point;
namespace swarm = mrd::tools::swarm;

Point vec(std::initializer_list<double> values) {
  Point p(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (const double v : values) p[i++] = v;
  return p;
}

TEST(InertiaWeight, FallsLinearlyFromMaxToMin) {  // Eq. 16
  EXPECT_DOUBLE_EQ(swarm::inertia_weight(0, 150, 0.8, 0.2), 0.8);
  EXPECT_DOUBLE_EQ(swarm::inertia_weight(75, 150, 0.8, 0.2), 0.5);
  EXPECT_DOUBLE_EQ(swarm::inertia_weight(150, 150, 0.8, 0.2), 0.2);
  EXPECT_DOUBLE_EQ(swarm::inertia_weight(300, 150, 0.8, 0.2), 0.2);  // no extrapolation
}

TEST(VelocityUpdate, MatchesEquation14ByHand) {
  // j=0: 0.5*1 + 2*0.25*(3-1) + 2*0.5*(5-1) = 0.5 + 1 + 4 = 5.5
  // j=1: 0.5*(-2) + 2*1.0*(0-2) + 2*0*(4-2) = -1 - 4 + 0 = -5, limited to -3
  ScriptedStream random({0.25, 0.5, 1.0, 0.0});
  const Point v = swarm::velocity_update(vec({1, -2}), vec({1, 2}), vec({3, 0}), vec({5, 4}),
                                         0.5, 2.0, 2.0, vec({10, 3}), random);
  EXPECT_DOUBLE_EQ(v[0], 5.5);
  EXPECT_DOUBLE_EQ(v[1], -3.0);
  EXPECT_TRUE(random.exhausted());
}

TEST(MoveParticle, StopsOnTheBoundAndLosesThatVelocity) {
  const Bounds bounds{vec({0, 0}), vec({10, 10})};
  Point x = vec({9, 5});
  Point v = vec({3, -1});
  swarm::move_particle(x, v, bounds);
  EXPECT_DOUBLE_EQ(x[0], 10.0);
  EXPECT_DOUBLE_EQ(v[0], 0.0);
  EXPECT_DOUBLE_EQ(x[1], 4.0);
  EXPECT_DOUBLE_EQ(v[1], -1.0);
}

TEST(PickDonors, DistinctAndNeverTheParticleItself) {
  // n = 5, exclude 2: candidates {0,1,3,4} indexed 0..3. u = 0.6 -> index 2 -> particle 3;
  // u = 0.6 again -> 3 taken, draw again; u = 0.1 -> particle 0; u = 0.9 -> particle 4.
  ScriptedStream random({0.6, 0.6, 0.1, 0.9});
  const auto d = swarm::pick_donors(5, 2, random);
  EXPECT_EQ(d.p1, 3u);
  EXPECT_EQ(d.p2, 0u);
  EXPECT_EQ(d.p3, 4u);
  EXPECT_TRUE(random.exhausted());
}

TEST(PickDonors, AlwaysDistinctOverManyDraws) {
  mrd::tools::SeededStream random(3);
  for (int trial = 0; trial < 10000; ++trial) {
    const std::size_t exclude = static_cast<std::size_t>(trial % 4);
    const auto d = swarm::pick_donors(4, exclude, random);
    std::vector<std::size_t> all{d.p1, d.p2, d.p3, exclude};
    std::sort(all.begin(), all.end());
    EXPECT_EQ(std::unique(all.begin(), all.end()), all.end());
  }
}

TEST(DeMutant, MatchesEquation18ByHand) {
  const Point h = swarm::de_mutant(vec({1, 2}), vec({5, 1}), vec({3, 4}), 0.5);
  EXPECT_DOUBLE_EQ(h[0], 2.0);   // 1 + 0.5 (5 - 3)
  EXPECT_DOUBLE_EQ(h[1], 0.5);   // 2 + 0.5 (1 - 4)
}

TEST(DeCrossover, TakesMutantWhereRandIsAtMostCrAndAtJRand) {
  // CR = 0.5: u = 0.2 (take h0), 0.7 (keep x1), 0.5 (take h2, <= is inclusive), 0.9 (keep
  // x3); then j_rand from u = 0.8 -> index 3, so component 3 comes from h as well.
  ScriptedStream random({0.2, 0.7, 0.5, 0.9, 0.8});
  const Point u = swarm::de_crossover(vec({10, 11, 12, 13}), vec({0, 1, 2, 3}), 0.5, random);
  EXPECT_EQ(u, vec({10, 1, 12, 13}));
  EXPECT_TRUE(random.exhausted());
}

TEST(DeSelect, TrialReplacesParentOnlyWhenNoWorse) {  // Eq. 20
  Point x = vec({1});
  double fx = 2.0;
  EXPECT_FALSE(swarm::de_select(x, fx, vec({5}), 2.5));
  EXPECT_EQ(x[0], 1.0);
  EXPECT_TRUE(swarm::de_select(x, fx, vec({6}), 2.0));  // equal fitness: the trial moves in
  EXPECT_EQ(x[0], 6.0);
  EXPECT_FALSE(swarm::de_select(x, fx, vec({7}), std::nan("")));
  EXPECT_EQ(fx, 2.0);
}

TEST(CauchyMutation, MatchesEquation22ByHandAndStaysInBounds) {
  // x + scale x C: 2 + 0.1*2*1.5 = 2.3; 4 + 0.1*4*(-3) = 2.8; 8 + 0.1*8*100 = 88 -> 10.
  ScriptedStream random({}, {1.5, -3.0, 100.0});
  const Bounds bounds{vec({0, 0, 0}), vec({10, 10, 10})};
  const Point y = swarm::cauchy_mutation(vec({2, 4, 8}), 0.1, bounds, random);
  EXPECT_DOUBLE_EQ(y[0], 2.3);
  EXPECT_DOUBLE_EQ(y[1], 2.8);
  EXPECT_DOUBLE_EQ(y[2], 10.0);
}

TEST(SeededStream, CauchyHasUnitMedianMagnitudeAndUniformIsInRange) {
  mrd::tools::SeededStream random(42);
  std::vector<double> magnitudes;
  for (int i = 0; i < 100001; ++i) {
    magnitudes.push_back(std::fabs(random.cauchy()));
    const double u = random.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
  }
  std::nth_element(magnitudes.begin(), magnitudes.begin() + 50000, magnitudes.end());
  EXPECT_NEAR(magnitudes[50000], 1.0, 0.02);  // |C(0,1)| has median tan(pi/4) = 1
}

TEST(SeededStream, SameSeedSameStream) {
  mrd::tools::SeededStream a(7), b(7);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(a.uniform(), b.uniform());
}

}  // namespace
