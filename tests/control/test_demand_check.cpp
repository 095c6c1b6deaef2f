// Force mode's demand check on its own, as PX4 tests its failsafe: a demand and a release time
// in, a verdict and the held demand out. It keeps the LVDT's checks that mean something for a
// number an outer controller sends and drops the two that do not (a held demand is no frozen
// sensor, a stepped one no jump).
#include "control/demand_check.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

namespace {

using namespace std::chrono_literals;
using mrd::control::DemandChecker;
using mrd::control::SampleCheck;
using mrd::hal::Sample;
using mrd::hal::Timestamp;

constexpr Timestamp kDemandMaxAge = 5ms;
constexpr double kDemandRange = 10e3;

DemandChecker demand_checker() { return DemandChecker({.range = kDemandRange, .max_age = kDemandMaxAge}); }

Sample demand(double newtons, Timestamp at, std::uint32_t sequence,
                    std::uint8_t flags = mrd::hal::kSampleValid) {
  return {newtons, at, sequence, flags};
}

TEST(DemandCheck, NothingYetIsMissingWithNothingHeld) {
  DemandChecker c = demand_checker();
  EXPECT_EQ(c.check(std::nullopt, 1s), SampleCheck::kMissing);
  EXPECT_FALSE(c.has_value());
  EXPECT_EQ(c.held_value(), 0.0);
}

TEST(DemandCheck, AGoodDemandIsHeldThroughEveryKindOfBadOne) {
  DemandChecker c = demand_checker();
  ASSERT_EQ(c.check(demand(2500.0, 1s, 1), 1s), SampleCheck::kFresh);
  EXPECT_TRUE(c.has_value());
  const struct {
    Sample sample;
    Timestamp now;
    SampleCheck verdict;
  } bad[] = {
      {demand(9000.0, 1s, 1), 1s + 1ms, SampleCheck::kStale},                       // its sequence again
      {demand(9000.0, 1s, 2), 1s + kDemandMaxAge + 1ms, SampleCheck::kStale},             // older than the age allowed
      {demand(9000.0, 2s, 3), 1s + 2ms, SampleCheck::kFromFuture},                  // stamped ahead of the release
      {demand(kDemandRange + 1.0, 1s + 3ms, 4), 1s + 3ms, SampleCheck::kOutOfRange},      // beyond the range
      {demand(-kDemandRange - 1.0, 1s + 4ms, 5), 1s + 4ms, SampleCheck::kOutOfRange},
      {demand(NAN, 1s + 5ms, 6), 1s + 5ms, SampleCheck::kNotFinite},
      {demand(9000.0, 1s + 6ms, 7, mrd::hal::kSampleValid | mrd::hal::kSampleCorrupted), 1s + 6ms,
       SampleCheck::kCorrupted},
  };
  for (const auto& b : bad) {
    EXPECT_EQ(c.check(b.sample, b.now), b.verdict) << b.sample.value;
    EXPECT_EQ(c.held_value(), 2500.0);  // the law keeps the last good demand
  }
  EXPECT_EQ(c.check(std::nullopt, 1s + 7ms), SampleCheck::kMissing);
  EXPECT_EQ(c.held_value(), 2500.0);
}

// The range's own ends are in range.
TEST(DemandCheck, TheRangesEndsAreGoodDemands) {
  DemandChecker c = demand_checker();
  EXPECT_EQ(c.check(demand(kDemandRange, 1s, 1), 1s), SampleCheck::kFresh);
  EXPECT_EQ(c.check(demand(-kDemandRange, 1s + 1ms, 2), 1s + 1ms), SampleCheck::kFresh);
  EXPECT_EQ(c.held_value(), -kDemandRange);
}

// A demand held for a thousand periods and then stepped across the whole range stays fresh:
// the LVDT's frozen and jump checks are not applied.
TEST(DemandCheck, AHeldOrSteppedDemandIsFresh) {
  DemandChecker c = demand_checker();
  Timestamp now = 1s;
  for (std::uint32_t i = 1; i <= 1000; ++i, now += 1ms)
    ASSERT_EQ(c.check(demand(1000.0, now, i), now), SampleCheck::kFresh) << i;
  EXPECT_EQ(c.check(demand(-kDemandRange, now, 1001), now), SampleCheck::kFresh);
  EXPECT_EQ(c.held_value(), -kDemandRange);
}

}  // namespace
